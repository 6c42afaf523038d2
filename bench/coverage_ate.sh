#!/usr/bin/env bash
# aco-ga against postman through the whole pipeline: `slamroute run` per seed (niced), then one
# table row per seed and the mean over seeds (bench/coverage_ate_table.py): directed coverage of
# the SUMO edges as driven, length in SUMO and its ratio to postman's, ATE RMSE and its ratio.
#   bench/coverage_ate.sh OUT_DIR [NET] [SEEDS]
# NET defaults to the shipped city, SEEDS to "42 1 2 3 4"; PLANNERS (env) to postman,aco-ga
# (other planners, e.g. open-loop,exhaustive-revisit, get a last table against postman),
# SLAMROUTE (env) to build/cli/slamroute (a copy keeps a long sweep on one build); PLANS_ONLY=1
# (env) stops each run once its routes are planned (directed coverage and length as planned, no
# SLAM: `run --plans-only`).
# A seed whose run finished is kept (`run --resume`), so an interrupted sweep continues.
source "$(dirname "$0")/script_help.sh" && exit_on_help "$0" "$@"
# Braced and ended by exit: bash parses the whole script before it runs, so an edit or a
# git pull during a long sweep does not change the sweep that is running.
{
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:?usage: bench/coverage_ate.sh OUT_DIR [NET] [SEEDS]}"
net="${2:-networks/default_city/default_city.net.xml}"
seeds="${3:-42 1 2 3 4}"
planners="${PLANNERS:-postman,aco-ga}"
bin="${SLAMROUTE:-build/cli/slamroute}"
only=""
if [ "${PLANS_ONLY:-0}" = 1 ]; then only="--plans-only"; fi
export SUMO_HOME="${SUMO_HOME:-/usr/share/sumo}"
mkdir -p "$out"
for s in $seeds; do
  start=$(date +%s)
  nice -n 10 "$bin" --seed "$s" run --net "$net" --out "$out/seed_$s" \
    --planners "$planners" --status-every 0 --resume $only >"$out/seed_$s.log" 2>&1
  echo "seed $s: $(( $(date +%s) - start )) s" >>"$out/times.txt"
done
# Debian's interpreter, for which scripts/setup.sh installs numpy and scipy.
/usr/bin/python3 bench/coverage_ate_table.py "$out" $seeds
exit
}
