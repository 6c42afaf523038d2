#!/usr/bin/env bash
# Memory of one SLAM run (bench/RESULTS.md "SLAM memory"): runs `slamroute evaluate` on a
# drive folder, samples its resident memory every INTERVAL seconds with the SLAM progress at that
# moment, and ends with the maximum resident set and the wall time from /usr/bin/time -v.
# Usage: bench/slam_memory.sh BUILD_DIR DRIVE_DIR OUT_DIR [INTERVAL_S=5] [CONFIG.yaml]
# Example: bench/slam_memory.sh build out/default_city/drives/qlearning out/slam_mem
# (CONFIG with `evaluate: {output: {keyframe_clouds_on_disk: false}}` measures the clouds kept in memory.)
source "$(dirname "$0")/script_help.sh" && exit_on_help "$0" "$@"
# Braced and ended by exit: bash parses the whole script before it runs, so an edit or a
# git pull during a long sweep does not change the sweep that is running.
{
set -euo pipefail
if [ $# -lt 3 ]; then
  echo "usage: $0 BUILD_DIR DRIVE_DIR OUT_DIR [INTERVAL_S] [CONFIG.yaml]" >&2
  exit 2
fi
bin="$1/cli/slamroute"
drive="$2"
out="$3"
every="${4:-5}"
config=()
[ $# -ge 5 ] && config=(--config "$5")
[ -x "$bin" ] || { echo "$0: $bin: not built" >&2; exit 1; }
[ -d "$drive" ] || { echo "$0: $drive: no such drive folder" >&2; exit 1; }
[ -x /usr/bin/time ] || { echo "$0: /usr/bin/time missing (Debian package 'time')" >&2; exit 1; }
mkdir -p "$out"
log="$out/evaluate.log"
/usr/bin/time -v "$bin" "${config[@]}" evaluate --drive "$drive" --out "$out/eval" > "$log" 2>&1 &
timer=$!
echo "| elapsed [s] | resident [kB] | SLAM progress |"
echo "|---|---|---|"
t=0
while kill -0 "$timer" 2>/dev/null; do
  sleep "$every"
  t=$((t + every))
  pid=$(pgrep -P "$timer" -f "evaluate --drive" | head -1 || true)
  [ -n "$pid" ] || continue
  rss=$(awk '/^VmRSS:/ {print $2}' "/proc/$pid/status" 2>/dev/null || true)
  progress=$(tail -c 400 "$log" | tr '\r' '\n' | grep "SLAM" | tail -1 || true)
  [ -n "$rss" ] && echo "| $t | $rss | ${progress#evaluate: } |"
done
wait "$timer"
grep -E "Maximum resident set size|Elapsed \(wall clock\)" "$log"
exit
}
