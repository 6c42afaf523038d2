#!/usr/bin/env bash
# Sweep throughput on this machine: bench/sweep_bench.yaml (32 tasks) with one rank running one
# task at a time, then `mpirun -n 2` (each rank one task at a time). Prints per setting the wall
# time, tasks per hour, the sum of the task run times (tasks.csv) and, for one rank (tasks back
# to back), the scheduler's overhead per task: (wall - sum of task times) / tasks.
#   bash bench/sweep_scaling.sh [OUT_DIR]   (default: build/bench_sweep)
source "$(dirname "$0")/script_help.sh" && exit_on_help "$0" "$@"
# Braced and ended by exit: bash parses the whole script before it runs, so an edit or a
# git pull during a long sweep does not change the sweep that is running.
{
set -euo pipefail
cd "$(dirname "$0")/.."
export SUMO_HOME="${SUMO_HOME:-/usr/share/sumo}"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
BIN="$PWD/build/cli/slamroute"
OUT="${1:-build/bench_sweep}"
rm -rf "$OUT" && mkdir -p "$OUT"

measure() {  # NAME COMMAND...
  local name="$1"; shift
  local t0 t1
  t0=$(date +%s.%N)
  "$@" > "$OUT/$name.log" 2>&1 || echo "$name: exit code $? (see $OUT/$name/failed_tasks.txt)"
  t1=$(date +%s.%N)
  python3 - "$OUT/$name" "$t0" "$t1" "$name" <<'PY'
import csv, sys
out, t0, t1, name = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), sys.argv[4]
rows = list(csv.DictReader(open(out + "/tasks.csv")))
wall = t1 - t0
busy = sum(float(r["seconds"]) for r in rows)
n = len(rows)
done = sum(r["state"] == "done" for r in rows)
print(f"{name}: {n} tasks ({done} done), wall {wall:.1f} s, {3600 * n / wall:.0f} tasks/h, "
      f"sum of task times {busy:.1f} s, (wall - sum) / tasks {(wall - busy) / n:.2f} s")
by = {}
for r in rows:
    kind = r["task"].rsplit("/", 1)[1].split(" ")[0]
    by.setdefault(kind, []).append(float(r["seconds"]))
print("  mean task time by kind: " + ", ".join(f"{k} {sum(v) / len(v):.1f} s" for k, v in by.items()))
PY
}

measure one_rank "$BIN" sweep bench/sweep_bench.yaml --out "$OUT/one_rank" --jobs 1
measure two_ranks mpirun --oversubscribe -n 2 "$BIN" sweep bench/sweep_bench.yaml --out "$OUT/two_ranks" --jobs 1
cmp -s "$OUT/one_rank/results.csv" "$OUT/two_ranks/results.csv" && echo "results.csv: the same with 1 and 2 ranks"
exit
}
