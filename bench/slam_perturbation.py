#!/usr/bin/env python3
# How stable a drive's SLAM result is: re-evaluates each drive with one weight or noise parameter
# of the evaluate config changed by -1 % and +1 % and prints, per drive, the baseline ATE RMSE, the
# range, how many evaluations stay within 20 % of the baseline, the largest relative change and the
# parameter that caused it, the ranges of accepted and refused loop closures, and the largest
# drift of a street kind over the evaluations, along the streets and end to end (bench/RESULTS.md
# "Stability").
# Usage: bench/slam_perturbation.py [--bin build/cli/slamroute] [--jobs 2] [--params lidar-only|S.K,..]
#        [--set SECTION.KEY=VALUE ...] [--seed 42] OUT_DIR DRIVE_DIR [DRIVE_DIR ...]
# (--params: the parameters to change, default all of PARAMS; "lidar-only" those that act when
# there is no wheel odometry)
# (--set evaluate settings every run starts from, e.g. --set odometry.use_wheel_odometry=false)
# Evaluations go to OUT_DIR/<drive>/<param>_<sign>/ (kept, so a rerun resumes); --report-only prints
# the table from the evaluations finished so far (how many of the 2 x len(PARAMS) + 1 per drive it
# says). Standard library only.
import argparse, concurrent.futures, json, os, subprocess, sys

# (section, key): the weights and noise figures of the SLAM (sigmas, robust kernel, blending).
PARAMS = [
    ("odometry", "prior_sigma_deg"), ("odometry", "prior_registration_sigma_m"),
    ("odometry", "imu_tilt_weight"), ("odometry", "wheel_translation_slack_m"),
    ("odometry", "wheel_rotation_slack_deg"), ("odometry", "slack_since_fix_max_s"),
    ("mapping", "huber_m"), ("mapping", "plane_max_dev_m"),
    ("loop", "graph_odom_sigma_m"), ("loop", "graph_odom_sigma_rad"), ("loop", "graph_loop_sigma_m"),
    ("loop", "graph_loop_sigma_rad"), ("loop", "fitness_m2"), ("loop", "graph_imu_pitch_sigma_deg"),
    ("loop", "graph_pitch_bias_sigma_deg"),
]
# Those that act without wheel odometry (the odometry prior and slacks do not), plus the motion
# model's turn figures and the constant velocity's yaw prior that only act then.
LIDAR_ONLY = [
    ("odometry", "imu_tilt_weight"), ("odometry", "failed_turn_decay"), ("odometry", "max_yaw_accel_deg_s2"),
    ("odometry", "velocity_prior_yaw_sigma_deg"), ("odometry", "velocity_prior_yaw_fade_info"),
    ("mapping", "huber_m"), ("mapping", "plane_max_dev_m"), ("loop", "graph_odom_sigma_m"),
    ("loop", "graph_loop_sigma_m"), ("loop", "fitness_m2"),
]


def defaults(binary):
    """Numeric evaluate defaults from `slamroute config --dump` (two-level YAML)."""
    out = subprocess.run([binary, "config", "--dump"], check=True, capture_output=True, text=True).stdout
    vals, top, sec = {}, None, None
    for line in out.splitlines():
        body = line.split("#")[0].rstrip()
        if not body.strip():
            continue
        indent = len(body) - len(body.lstrip())
        key, _, val = body.strip().partition(":")
        if indent == 0:
            top = key
        elif indent == 2:
            sec = key
        elif indent == 4 and top == "evaluate" and val.strip():
            try:
                vals[(sec, key)] = float(val)
            except ValueError:
                pass
    return vals


def to_yaml(cfg):
    lines = ["evaluate:"] + [f"  {sec}:\n" + "\n".join(f"    {k}: {v}" for k, v in kv.items())
                              for sec, kv in cfg.items()]
    return "\n".join(lines) + ("\n" if cfg else " {}\n")


def evaluate(binary, seed, drive, out, yaml_text, report_only=False):
    """metrics.json of one evaluation (run unless it exists); None when --report-only lacks it."""
    metrics = os.path.join(out, "metrics.json")
    if report_only:
        return json.load(open(metrics)) if os.path.exists(metrics) else None
    if not os.path.exists(metrics):
        os.makedirs(os.path.dirname(out), exist_ok=True)
        cfg = out + ".yaml"
        with open(cfg, "w") as f:
            f.write(yaml_text)
        r = subprocess.run([binary, "--seed", str(seed), "--log-level", "warn", "--config", cfg, "evaluate",
                            "--drive", drive, "--out", out], capture_output=True, text=True)
        if r.returncode != 0:
            sys.exit(f"{drive}: evaluate failed: {r.stderr.strip().splitlines()[-1:]}")
    return json.load(open(metrics))


def spread(runs, key):
    """'lo-hi' of one metrics.json count over a drive's evaluations."""
    vals = [int(m.get(key, 0)) for m in runs]
    return f"{min(vals)}-{max(vals)}" if min(vals) != max(vals) else str(vals[0])


def largest_drift(runs):
    """'along (kind) / end to end (kind)': the largest street kind's drift [%] over a drive's
    evaluations (metrics.json drift_by_label window_drift_pct / drift_pct); '-' where none."""
    def worst(key):
        vals = [(d[key], kind) for m in runs for kind, d in m.get("drift_by_label", {}).items()
                if d.get(key) is not None]
        if not vals:
            return "-"
        v, kind = max(vals)
        return f"{v:.2f} ({kind})"
    return f"{worst('window_drift_pct')} / {worst('drift_pct')}"


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--bin", default="build/cli/slamroute")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--set", action="append", default=[], metavar="SECTION.KEY=VALUE",
                    help="an evaluate setting every run starts from")
    ap.add_argument("--seed", type=int, default=42)
    ap.add_argument("--params", default="", help='"lidar-only" or SECTION.KEY,... (default: all)')
    ap.add_argument("--report-only", action="store_true", help="no evaluations: the table of those done")
    ap.add_argument("out")
    ap.add_argument("drives", nargs="+")
    a = ap.parse_args()
    base = {}
    for item in a.set:
        path, _, val = item.partition("=")
        sec, _, key = path.partition(".")
        if not (sec and key and val):
            sys.exit(f"--set {item}: expected SECTION.KEY=VALUE")
        base.setdefault(sec, {})[key] = val
    params = PARAMS
    if a.params == "lidar-only":
        params = LIDAR_ONLY
    elif a.params:
        params = [tuple(p.split(".", 1)) for p in a.params.split(",")]
    dflt = defaults(a.bin)
    missing = [p for p in params if p not in dflt]
    if missing:
        sys.exit(f"{a.bin}: config --dump lacks {missing}")
    jobs = []
    for d in a.drives:
        name = os.path.basename(os.path.normpath(d))
        jobs.append((d, name, "base", to_yaml(base)))
        for sec, key in params:
            for sign, f in (("minus", 0.99), ("plus", 1.01)):
                cfg = {k: dict(v) for k, v in base.items()}
                cfg.setdefault(sec, {})[key] = repr(dflt[(sec, key)] * f)
                jobs.append((d, name, f"{sec}.{key}_{sign}", to_yaml(cfg)))
    with concurrent.futures.ThreadPoolExecutor(a.jobs) as ex:
        futs = {ex.submit(evaluate, a.bin, a.seed, d, os.path.join(a.out, n, tag), y, a.report_only): (n, tag)
                for d, n, tag, y in jobs}
        done = {futs[f]: f.result() for f in concurrent.futures.as_completed(futs)}
    found = {k: m for k, m in done.items() if m is not None}
    print("| drive | evaluations | ATE RMSE [m] | ATE range over +-1 % [m] | within +-20 % | "
          "largest change [%] | caused by | closures | refused as ambiguous | refused by correction or cycle | "
          "largest drift per street kind, along / end to end [%] |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for d in a.drives:
        n = os.path.basename(os.path.normpath(d))
        runs = {t: m["ate_rmse_m"] for (dn, t), m in found.items() if dn == n and t != "base"}
        if (n, "base") not in found or not runs:
            print(f"| {n} | {len(runs)} of {2 * len(params)} | - | - | - | - | - | - | - | - | - |")
            continue
        base = found[(n, "base")]["ate_rmse_m"]
        worst = max(runs, key=lambda t: abs(runs[t] - base))
        lo, hi = min(runs.values()), max(runs.values())
        within = sum(abs(v - base) <= 0.2 * base for v in runs.values())
        every = [m for (dn, _), m in found.items() if dn == n]
        print(f"| {n} | {len(runs)} of {2 * len(params)} | {base:.3f} | {lo:.3f} - {hi:.3f} | "
              f"{within} of {len(runs)} | {100 * abs(runs[worst] - base) / base:.1f} | {worst} | "
              f"{spread(every, 'loop_closures')} | {spread(every, 'loops_rejected_ambiguous')} | "
              f"{spread(every, 'loops_rejected_correction')} | {largest_drift(every)} |")


if __name__ == "__main__":
    main()
