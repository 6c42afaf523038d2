#!/bin/sh
# Regenerates every shipped SUMO network (plain XML in networks/plain/ -> netconvert -> .net.xml)
# and checks them. Usage: networks/generate.sh [--simulate]   (needs sumo + sumo-tools)
set -eu
cd "$(dirname "$0")"
export SUMO_HOME="${SUMO_HOME:-/usr/share/sumo}"
python3 generate.py
python3 check.py "$@"
