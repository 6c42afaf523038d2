#!/usr/bin/env bash
# Set-up, build and the whole test suite (what CI runs).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
export SUMO_HOME="${SUMO_HOME:-/usr/share/sumo}"
bash scripts/build.sh
ctest --test-dir build --output-on-failure -j2 --timeout 900
