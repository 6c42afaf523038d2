#!/usr/bin/env bash
# Set-up, build and the main job on the shipped default city. Output in ./out/default_city.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
export SUMO_HOME="${SUMO_HOME:-/usr/share/sumo}"
bash scripts/build.sh
./build/slamroute run --out out/default_city "$@"
