#!/usr/bin/env python3
"""Node F1 over a grid of roadgraph.nodes settings on one net (bench/RESULTS.md, "Node F1 on nets
not used for tuning", the 144-setting grid on Bologna).

Usage: bench/node_f1_grid.py BUILD_DIR SURVEYS_DIR NAME NET.net.xml "SEEDS" OUT.tsv

Reads the surveys SURVEYS_DIR/NAME<seed> that bench/node_f1_sweep.sh makes, builds the graph for
every combination of the values in GRID and appends one line per setting to OUT.tsv: the setting,
F1 per seed, the lowest and the mean. A setting already in OUT.tsv is skipped, so an interrupted
grid continues. Standard library only; one build-graph at a time (~2 s each on Bologna).
"""
import itertools
import json
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from script_help import exit_on_help  # noqa: E402

GRID = {
    "inner_radius_m": [8, 9, 10],
    "outer_radius_m": [20, 22, 25],
    "merge_distance_m": [14, 16, 18, 20],
    "node_radius_m": [10, 12],
    "min_vote_fraction": [0.25, 0.35],
}


def main():
    exit_on_help(__doc__)
    if len(sys.argv) != 7:
        sys.exit(__doc__)
    build, surveys, name, net, seeds, out_path = sys.argv[1:]
    binary = os.path.join(build, "cli", "slamroute")
    for path in [binary, net] + [os.path.join(surveys, f"{name}{s}", "traces.csv") for s in seeds.split()]:
        if not os.path.isfile(path):
            sys.exit(f"node_f1_grid.py: {path}: no such file (surveys come from bench/node_f1_sweep.sh)")
    done = set()
    if os.path.exists(out_path):
        with open(out_path) as f:
            done = {line.split("\t")[0] for line in f}
    cfg = out_path + ".yaml"
    graph = out_path + ".graph.json"
    with open(out_path, "a") as out:
        for values in itertools.product(*GRID.values()):
            key = " ".join(f"{k}={v}" for k, v in zip(GRID, values))
            if key in done:
                continue
            with open(cfg, "w") as f:
                f.write("roadgraph:\n  nodes:\n" + "".join(f"    {k}: {v}\n" for k, v in zip(GRID, values)))
            f1 = []
            for s in seeds.split():
                run = subprocess.run([binary, "--log-level", "error", "--config", cfg, "build-graph", "--survey",
                                      os.path.join(surveys, f"{name}{s}"), "--no-depth", "--net", net, "--out",
                                      graph], stdout=subprocess.DEVNULL)
                if run.returncode != 0:
                    sys.exit(f"node_f1_grid.py: build-graph failed on {name}{s} with {key}")
                with open(graph) as f:
                    f1.append(json.load(f)["metadata"]["validation"]["node_f1"])
            out.write(f"{key}\t{' '.join('%.3f' % x for x in f1)}\t{min(f1):.3f}\t{sum(f1) / len(f1):.3f}\n")
            out.flush()


if __name__ == "__main__":
    main()
