#!/usr/bin/env bash
# Node F1 of build-graph over survey seeds and roadgraph.nodes settings on the shared nets
# (bench/RESULTS.md, "Node F1 over survey seeds", parameter sweep) or on other nets.
# Usage: bench/node_f1_sweep.sh [BUILD_DIR] [OUT_DIR] [SEEDS]
# Surveys are made once (--depth-spacing 0: traces only) and reused; each setting then builds the
# graph from all of them (~30 s per setting on 2 cores). Prints one Markdown row per setting:
# F1 per seed and the mean, per net (default: Bologna then Ingolstadt).
# NETS="name=NET.net.xml ..." sweeps other nets instead, e.g. the held-out nets of RESULTS.md
# "Node F1 on nets not used for tuning" (the real city nets Debian's sumo-tools ships):
#   NETS="pasubio=/usr/share/sumo/tools/sumolib/scenario/scenarios/RealWorld/pasubio/pasubio_buslanes.net.xml
#         braunschweig=/usr/share/sumo/tools/game/bs3d/bs.net.xml drt=/usr/share/sumo/tools/game/DRT/osm.net.xml"
# SWEEP_ONLY=N keeps the first N settings (1: the defaults only).
# Bologna and Ingolstadt are read from ../shared/networks beside the clone (not shipped: see
# networks/README.md); a clone without that folder passes other nets through NETS.
source "$(dirname "$0")/script_help.sh" && exit_on_help "$0" "$@"
# Braced and ended by exit: bash parses the whole script before it runs, so an edit or a
# git pull during a long sweep does not change the sweep that is running.
{
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
build="${1:-$here/../build}"
out="${2:-/tmp/slamroute_node_f1}"
seeds="${3:-42 7 1 2 3}"
bin="$build/cli/slamroute"
shared="$here/../../shared/networks"
declare -A net=()
names=()
for entry in ${NETS:-bologna=$shared/bologna_acosta/acosta_buslanes.net.xml ingolstadt=$shared/ingolstadt21/ingolstadt21.net.xml}; do
  name="${entry%%=*}"; path="${entry#*=}"
  [ -f "$path" ] || { echo "node_f1_sweep.sh: $path: no such net" >&2; exit 2; }
  net[$name]="$path"; names+=("$name")
done
mkdir -p "$out/graphs"
for n in "${names[@]}"; do
  for s in $seeds; do
    [ -f "$out/$n$s/traces.csv" ] ||
      "$bin" --log-level warn --seed "$s" survey --net "${net[$n]}" --out "$out/$n$s" --depth-spacing 0
  done
done

# name | YAML lines under roadgraph.nodes (';'-separated), empty = defaults
settings=(
  "defaults|"
  "merge_distance_m 12|merge_distance_m: 12"
  "merge_distance_m 14|merge_distance_m: 14"
  "merge_distance_m 16|merge_distance_m: 16"
  "merge_distance_m 20|merge_distance_m: 20"
  "merge_distance_m 22|merge_distance_m: 22"
  "merge_distance_m 25|merge_distance_m: 25"
  "node_radius_m 8|node_radius_m: 8"
  "node_radius_m 12|node_radius_m: 12"
  "node_radius_m 14|node_radius_m: 14"
  "inner_radius_m 8|inner_radius_m: 8"
  "inner_radius_m 12|inner_radius_m: 12"
  "outer_radius_m 22|outer_radius_m: 22"
  "outer_radius_m 28|outer_radius_m: 28"
  "min_vote_fraction 0.15|min_vote_fraction: 0.15"
  "min_vote_fraction 0.35|min_vote_fraction: 0.35"
  "refine_centre true|refine_centre: true"
  "outer 22, node_radius 12, merge 20|outer_radius_m: 22;node_radius_m: 12;merge_distance_m: 20"
  "node_radius 12, merge 20, min_vote_fraction 0.35|node_radius_m: 12;merge_distance_m: 20;min_vote_fraction: 0.35"
)
[ -n "${SWEEP_ONLY:-}" ] && settings=("${settings[@]:0:$SWEEP_ONLY}")

cfg="$out/sweep.yaml"
f1() {  # graph.json -> node F1
  python3 -c 'import json,sys; print("%.3f" % json.load(open(sys.argv[1]))["metadata"]["validation"]["node_f1"])' "$1"
}
header="| setting"; rule="|---"
for n in "${names[@]}"; do header="$header | $n per seed ($seeds) | mean"; rule="$rule|---|---"; done
echo "$header |"; echo "$rule|"
for entry in "${settings[@]}"; do
  name="${entry%%|*}"; body="${entry#*|}"
  if [ -z "$body" ]; then echo "{}" > "$cfg"; else
    { echo "roadgraph:"; echo "  nodes:"; IFS=';' read -ra kv <<< "$body"
      for l in "${kv[@]}"; do echo "    $l"; done; } > "$cfg"; fi
  row="| $name"
  for n in "${names[@]}"; do
    vals=()
    for s in $seeds; do
      g="$out/graphs/$n$s.json"
      "$bin" --log-level error --config "$cfg" build-graph --survey "$out/$n$s" --no-depth \
        --net "${net[$n]}" --out "$g" > /dev/null
      vals+=("$(f1 "$g")")
    done
    mean=$(printf '%s\n' "${vals[@]}" | awk '{s+=$1} END {printf "%.3f", s/NR}')
    row="$row | $(IFS=' '; echo "${vals[*]}" | sed 's/ / \/ /g') | $mean"
  done
  echo "$row |"
done
exit
}
