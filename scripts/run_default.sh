#!/usr/bin/env bash
# Set-up, build and the main job on the shipped default city. Output in ./out/default_city.
# Extra arguments go to `slamroute run` (e.g. --planners qlearning,postman).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
export SUMO_HOME="${SUMO_HOME:-/usr/share/sumo}"
bash scripts/build.sh
# The program scripts/build.sh builds (tests/cli/ScriptsTest.cpp checks this path).
bin=./build/cli/slamroute
"$bin" run --out out/default_city "$@"
