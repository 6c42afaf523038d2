#!/usr/bin/env python3
"""The aco-ga vs postman table of bench/coverage_ate.sh from OUT_DIR/seed_S/{routes,eval}.

Per seed and the mean +- sd over the seeds that finished: directed SUMO edges driven [%] (the
drive as evaluated), route length in SUMO [km], aco-ga / postman length, ATE RMSE [m],
aco-ga / postman ATE; a seed whose SLAM has not run shows its planned coverage and length.
Then where the ATE comes from: the SLAM's loop closures per km driven and the largest error
per planner, and aco-ga's planned revisits (count, length) and its predicted C_max against the
bound. Directed coverage counts the net's part a car can drive round legally (turns included);
a further table gives the junction-level part (turns ignored) and how many of its edges no legal
drive enters and leaves again. When the runs also drove other planners (PLANNERS of
bench/coverage_ate.sh, e.g. open-loop and exhaustive-revisit), a last table sets each against
postman on the same seeds: length and ATE ratios, revisits, and the ATE on the first passes
alone (the poses of each SUMO edge's first traversal, under the evaluation's alignment): driving
mapped streets again adds poses of low error, which lowers a drive's ATE even where the streets
as first driven are no better. Usage: coverage_ate_table.py OUT_DIR SEED [SEED ...]
Needs numpy and scipy (Debian python3-numpy, python3-scipy)."""
import functools
import json
import os
import statistics
import sys
from pathlib import Path

import numpy as np
from scipy.spatial.transform import Rotation

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from first_passes import FirstPasses  # noqa: E402
from script_help import exit_on_help  # noqa: E402
from tum import load_tum  # noqa: E402

NAME = "coverage_ate_table.py"


def load(path):
    return json.loads(path.read_text()) if path.exists() else None


def figures(run, planner):
    """(directed coverage %, SUMO length km, ATE RMSE m) or None without a route. Coverage as
    driven once the SLAM has run, else as planned; ATE None until the SLAM has run."""
    route = load(run / "routes" / f"{planner}.json")
    metrics = load(run / "eval" / planner / "metrics.json")
    if route is None:
        return None
    cov = (metrics or {}).get("directed_coverage", route.get("directed_coverage", {}))
    km = route["sumo_length"]["total_m"] / 1000.0
    return cov["edges_pct"], km, metrics["ate_rmse_m"] if metrics else None


def mean_sd(values, digits):
    if not values:
        return "–"
    sd = statistics.stdev(values) if len(values) > 1 else 0.0
    return f"{statistics.mean(values):.{digits}f} ± {sd:.{digits}f}"


def main():
    out, seeds = Path(sys.argv[1]), sys.argv[2:]
    print("| seed | postman directed [%] | aco-ga directed [%] | postman km | aco-ga km | "
          "length ratio | postman ATE [m] | aco-ga ATE [m] | ATE ratio |")
    print("|---|---|---|---|---|---|---|---|---|")
    cols = {k: [] for k in ("pd", "ad", "pk", "ak", "lr", "pa", "aa", "ar")}
    for s in seeds:
        p, a = figures(out / f"seed_{s}", "postman"), figures(out / f"seed_{s}", "aco-ga")
        if p is None or a is None:
            print(f"| {s} | not planned |||||||| ")
            continue
        row = dict(pd=p[0], ad=a[0], pk=p[1], ak=a[1], lr=a[1] / p[1])
        ate = "SLAM not run | – | –"
        if p[2] is not None and a[2] is not None:
            row.update(pa=p[2], aa=a[2], ar=a[2] / p[2])
            ate = f"{p[2]:.3f} | {a[2]:.3f} | {row['ar']:.2f}"
        for k, v in row.items():
            cols[k].append(v)
        print(f"| {s} | {p[0]:.1f} | {a[0]:.1f} | {p[1]:.2f} | {a[1]:.2f} | {row['lr']:.3f} | "
              f"{ate} |")
    digits = dict(pd=1, ad=1, pk=2, ak=2, lr=3, pa=3, aa=3, ar=2)
    print(f"| mean ± sd ({len(cols['lr'])} seeds; ATE {len(cols['ar'])}) | "
          + " | ".join(mean_sd(cols[k], digits[k]) for k in cols) + " |")


def closures(run, planner):
    """(SLAM loop closures, closures per km evaluated, ATE max m) or None if not finished."""
    metrics = load(run / "eval" / planner / "metrics.json")
    if metrics is None:
        return None
    km = metrics["evaluated_length_m"] / 1000.0
    return metrics["loop_closures"], metrics["loop_closures"] / km, metrics["ate_max_m"]


def diagnostics(out, seeds):
    rows = []
    for s in seeds:
        run = out / f"seed_{s}"
        p, a = closures(run, "postman"), closures(run, "aco-ga")
        route = load(run / "routes" / "aco-ga.json")
        if p is None or a is None or route is None:
            continue
        extra = route["extra"]
        unc = extra["uncertainty"]
        rows.append(f"| {s} | {p[0]} ({p[1]:.1f}) | {a[0]} ({a[1]:.1f}) | "
                    f"{p[2]:.2f} / {a[2]:.2f} | {extra['loop_closure_revisits']}, "
                    f"{extra['revisit_length_m'] / 1000.0:.2f} | "
                    f"{unc['c_max_m2']:.0f} / {unc['c_threshold_m2']:.0f} |")
    print_table(["seed", "postman closures (per km)", "aco-ga closures (per km)",
                 "postman / aco-ga ATE max [m]", "aco-ga revisits, length [km]",
                 "aco-ga C_max / bound [m^2]"], rows)


def print_table(header, rows):
    """A markdown table after a blank line; nothing without rows."""
    if rows:
        print()
        print("| " + " | ".join(header) + " |")
        print("|" + "---|" * len(header))
        print("\n".join(rows))


def junction_part(out, seeds):
    """Per seed: the directed figure over the junction-level part, planned, and its edges."""
    rows = []
    for s in seeds:
        cov = [(load(out / f"seed_{s}" / "routes" / f"{p}.json") or {}).get("directed_coverage", {})
               for p in ("postman", "aco-ga")]
        if all("junction_part" in c for c in cov):
            j = [c["junction_part"] for c in cov]
            rows.append(f"| {s} | {cov[0]['edges_total']} of {j[0]['edges_total']} "
                        f"({j[0]['edges_without_legal_route']} without) | "
                        f"{j[0]['edges_pct']:.1f} | {j[1]['edges_pct']:.1f} |")
    print_table(["seed", "legal part of the junction-level part, edges (without a legal route)",
                 "postman junction-level [%]", "aco-ga junction-level [%]"], rows)


@functools.lru_cache(maxsize=None)
def first_pass_ate(run, planner):
    """RMS position error [m] on the poses of each SUMO edge's first traversal, under the
    evaluation's alignment (metrics.json)."""
    drive, ev = run / "drives" / planner, run / "eval" / planner
    align = load(ev / "metrics.json")["alignment_T_gt_est"]
    gt = load_tum(str(drive / "groundtruth.tum"), NAME)
    est = load_tum(str(ev / "estimate.tum"), NAME)
    first = FirstPasses(str(drive), NAME).mask(est[:, 0])
    if not first.any():
        return float("nan")
    g = gt[np.minimum(np.searchsorted(gt[:, 0], est[first, 0] - 1e-6), len(gt) - 1)]
    p = Rotation.from_quat(align["q_xyzw"]).apply(est[first, 1:4]) + np.array(align["t"])
    return float(np.sqrt(((p - g[:, 1:4]) ** 2).sum(1).mean()))


def against_postman(out, seeds):
    """Every other planner with an evaluated drive on at least one seed, against postman."""
    names = sorted({d.name for s in seeds for d in (out / f"seed_{s}" / "eval").glob("*")
                    if d.name not in ("postman", "fleet") and (d / "metrics.json").exists()})
    rows = []
    for name in names:
        lr, ar, ate, revisits, fr = [], [], [], [], []
        for s in seeds:
            run = out / f"seed_{s}"
            p, o = figures(run, "postman"), figures(run, name)
            if p is None or o is None or p[2] is None or o[2] is None:
                continue
            lr.append(o[1] / p[1])
            ar.append(o[2] / p[2])
            ate.append(o[2])
            extra = (load(run / "routes" / f"{name}.json") or {}).get("extra", {})
            revisits.append(extra.get("loop_closure_revisits", 0))
            fr.append(first_pass_ate(run, name) / first_pass_ate(run, "postman"))
        if ar:
            per_seed = ", ".join(f"{r:.2f}" for r in ar)
            rows.append(f"| {name} | {len(ar)} | {mean_sd(lr, 3)} | {mean_sd(ate, 3)} | "
                        f"{mean_sd(ar, 2)} ({per_seed}) | {mean_sd(fr, 2)} | "
                        f"{mean_sd(revisits, 1)} |")
    print_table(["planner", "seeds", "length / postman", "ATE RMSE [m]",
                 "ATE / postman (per seed)", "first-pass ATE / postman", "revisits"], rows)


if __name__ == "__main__":
    exit_on_help(__doc__)
    if len(sys.argv) < 3:
        sys.exit("usage: bench/coverage_ate_table.py OUT_DIR SEED [SEED ...]")
    main()
    diagnostics(Path(sys.argv[1]), sys.argv[2:])
    junction_part(Path(sys.argv[1]), sys.argv[2:])
    against_postman(Path(sys.argv[1]), sys.argv[2:])
