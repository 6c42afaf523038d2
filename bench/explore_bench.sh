#!/usr/bin/env bash
# `slamroute explore` over the default city, Bologna, Ingolstadt and Berlin-Adlershof for
# K = 1, 2, 4 and every strategy (bench/RESULTS.md, "Online exploration"). Prints one Markdown
# row per run: streets, distance to 95 % of the directed streets over the offline fleet bound
# (the summed closed routes of K vehicles that know the map, rl planFleet from the same starts),
# simulated time to 95 % and 100 %, compute per decision. Usage: bench/explore_bench.sh [BUILD_DIR] [OUT_DIR] [NETS...]
#   NETS: default bologna ingolstadt adlershof (all when none given). Runs one after another.
#   KS (environment): the fleet sizes, default "1 2 4"; STRATEGIES likewise.
# Bologna and Ingolstadt are read from ../shared/networks beside the clone (not shipped: see
# networks/README.md); without that folder name the other nets.
source "$(dirname "$0")/script_help.sh" && exit_on_help "$0" "$@"
# Braced and ended by exit: bash parses the whole script before it runs, so an edit or a
# git pull during a long sweep does not change the sweep that is running.
{
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
build="${1:-$here/../build}"
out="${2:-/tmp/slamroute_explore_bench}"
shift $(( $# > 2 ? 2 : $# ))
nets=("$@")
[ ${#nets[@]} -gt 0 ] || nets=(default bologna ingolstadt adlershof)
bin="$build/cli/slamroute"
export SUMO_HOME="${SUMO_HOME:-/usr/share/sumo}"
mkdir -p "$out"
net_path() {
  case $1 in
    default) echo "$here/../networks/default_city/default_city.net.xml" ;;
    bologna) echo "$here/../../shared/networks/bologna_acosta/acosta_buslanes.net.xml" ;;
    ingolstadt) echo "$here/../../shared/networks/ingolstadt21/ingolstadt21.net.xml" ;;
    adlershof) echo "/usr/share/sumo/tools/game/DRT/osm.net.xml" ;;
  esac
}
echo "| net | K | strategy | streets driven | bound [km] | dist. to 95 % / bound | time to 95 % [s] | time to 100 % [s] | ms / decision (mean, max) | wall [s] |"
echo "|---|---|---|---|---|---|---|---|---|---|"
for net in "${nets[@]}"; do
  for k in ${KS:-1 2 4}; do
    for s in ${STRATEGIES:-nearest gp-frontier fleet central siba}; do
      dir="$out/$net/k$k/$s"
      t0=$(date +%s.%N)
      if ! "$bin" --log-level warn explore --net "$(net_path "$net")" --vehicles "$k" --strategy "$s" --out "$dir" > /dev/null 2> "$out/$net-k$k-$s.err"; then
        echo "| $net | $k | $s | failed: $(tail -1 "$out/$net-k$k-$s.err") | | | | | | |"
        continue
      fi
      wall=$(echo "$(date +%s.%N) - $t0" | bc)
      python3 - "$dir" "$net" "$k" "$s" "$wall" <<'PY'
import json, sys
d, net, k, s, wall = sys.argv[1:]
j = json.load(open(d + "/explore.json")); t = json.load(open(d + "/timing.json"))
m = {round(x["share"] * 100): x for x in j["milestones"]}
ratio = lambda x: "%.2f" % x["fleet_distance_over_bound"] if x["reached"] else "–"
time = lambda x: "%.0f" % x["time_s"] if x["reached"] else "–"
print("| %s | %s | %s | %d / %d | %.1f | %s | %s | %s | %.2f, %.1f | %.0f |" % (
    net, k, s, j["streets_driven"], j["directed_streets"], j["offline_bound_m"] / 1000, ratio(m[95]), time(m[95]),
    time(m[100]), t["mean_ms"], t["max_ms"], float(wall)))
PY
    done
  done
done
exit
}
