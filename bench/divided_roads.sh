#!/usr/bin/env bash
# Node and edge accuracy of build-graph on nets with divided roads (bench/RESULTS.md, "Divided
# roads"): junction level (every SUMO junction with >= 3 neighbours is one intersection) and
# place level (the carriageway crossings of a divided road, and the corners of a junction box,
# are one place; a divided road is one street; roadgraph.sumo.place_link_max_m).
# Usage: bench/divided_roads.sh [BUILD_DIR] [OUT_DIR] [SEEDS] [CONFIG.yaml]
# Surveys (--depth-spacing 0: traces only) are made once per net and seed and reused. Prints one
# Markdown row per net and seed: junction-level node P / R / F1 and edge P / R, then the same at
# place level. NETS="name=NET.net.xml ..." replaces the default list.
# Bologna and Ingolstadt are read from ../shared/networks beside the clone (not shipped: see
# networks/README.md); a clone without that folder passes other nets through NETS.
source "$(dirname "$0")/script_help.sh" && exit_on_help "$0" "$@"
# Braced and ended by exit: bash parses the whole script before it runs, so an edit or a
# git pull during a long sweep does not change the sweep that is running.
{
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
build="${1:-$here/../build}"
out="${2:-/tmp/slamroute_divided}"
seeds="${3:-42}"
config="${4:-}"
bin="$build/cli/slamroute"
export SUMO_HOME="${SUMO_HOME:-/usr/share/sumo}"
shared="$here/../../shared/networks"
default_nets="divided_avenue=$here/../networks/test/divided_avenue.net.xml
  divided_cross=$here/../networks/test/divided_cross.net.xml
  adlershof=$SUMO_HOME/tools/game/DRT/osm.net.xml
  braunschweig=$SUMO_HOME/tools/game/bs3d/bs.net.xml
  default_city=$here/../networks/default_city/default_city.net.xml
  bologna=$shared/bologna_acosta/acosta_buslanes.net.xml
  ingolstadt=$shared/ingolstadt21/ingolstadt21.net.xml"
mkdir -p "$out/graphs"
cfg_arg=()
[ -n "$config" ] && cfg_arg=(--config "$config")
echo "| net | seed | junctions: node P / R / F1 | edge P / R | places: node P / R / F1 | edge P / R |"
echo "|---|---|---|---|---|---|"
for entry in ${NETS:-$default_nets}; do
  name="${entry%%=*}"; net="${entry#*=}"
  [ -f "$net" ] || { echo "divided_roads.sh: $net: no such net" >&2; exit 2; }
  for s in $seeds; do
    sv="$out/$name$s"
    [ -f "$sv/traces.csv" ] ||
      "$bin" --log-level warn --seed "$s" survey --net "$net" --out "$sv" --depth-spacing 0 >/dev/null
    g="$out/graphs/$name$s.json"
    "$bin" --log-level error "${cfg_arg[@]}" build-graph --survey "$sv" --no-depth --net "$net" \
      --out "$g" >/dev/null
    python3 - "$g" "$name" "$s" <<'PY'
import json, sys
meta = json.load(open(sys.argv[1]))["metadata"]
if isinstance(meta, str):
    meta = json.loads(meta)
def cells(v):
    return ("%.3f / %.3f / %.3f" % (v["node_precision"], v["node_recall"], v["node_f1"]),
            "%.3f / %.3f" % (v["edge_precision"], v["edge_recall"]))
j, p = cells(meta["validation"]), cells(meta["place_validation"])
print("| %s | %s | %s | %s | %s | %s |" % (sys.argv[2], sys.argv[3], j[0], j[1], p[0], p[1]))
PY
  done
done
exit
}
