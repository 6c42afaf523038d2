#!/usr/bin/env bash
# Set-up, build and the whole test suite (what CI runs).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
# Every tracked C++ source follows .clang-format (scripts/check_format.sh);
# SLAMROUTE_CHECK_FORMAT=0 skips the check.
if [ "${SLAMROUTE_CHECK_FORMAT:-1}" = 1 ]; then
  bash scripts/check_format.sh
fi
export SUMO_HOME="${SUMO_HOME:-/usr/share/sumo}"
bash scripts/build.sh
ctest --test-dir build --output-on-failure -j2 --timeout 900
