#!/usr/bin/env python3
# False loop closures over a set of evaluations: an accepted closure (metrics.json "loops") is
# false when the relative pose its ICP measured between the two keyframes is more than
# --max-error-m (default 1 m) off the ground truth's relative pose. Prints a Markdown table, one
# row per evaluation and a total; exits 0 either way.
# Usage: bench/false_closures.py [--max-error-m M] PATH [PATH ...], each PATH either an
# `experiment` / `run` output folder (eval/NAME evaluated from drives/NAME) or EVAL_DIR:DRIVE_DIR.
# Python 3 standard library only.
import argparse, glob, json, os, sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from loop_closure_check import closure_errors, ground_truth_at  # noqa: E402


def evaluations(path):  # (name, eval dir, drive dir) for one command-line PATH
    if ':' in path:
        ev, dr = path.split(':', 1)
        return [(os.path.basename(ev.rstrip('/')), ev, dr)]
    found = []
    for ev in sorted(glob.glob(os.path.join(path, 'eval', '*'))):
        if os.path.exists(os.path.join(ev, 'metrics.json')):
            name = os.path.basename(ev)
            found.append((os.path.basename(path.rstrip('/')) + '/' + name, ev,
                          os.path.join(path, 'drives', name)))
    if not found:
        sys.exit('false_closures.py: %s: no eval/*/metrics.json (and not EVAL_DIR:DRIVE_DIR)'
                 % path)
    return found


def row(name, ev, dr, max_error_m):
    m = json.load(open(os.path.join(ev, 'metrics.json')))
    errors = closure_errors(ground_truth_at(dr), m.get('loops', []))
    known = [e for e in errors if e[0] is not None]
    false = [e for e in known if e[0] > max_error_m]
    worst = max((e[0] for e in known), default=None)
    worst_yaw = max((e[1] for e in known if e[1] is not None), default=None)
    return name, len(errors), len(errors) - len(known), len(false), worst, worst_yaw


def fmt(v):
    return '-' if v is None else '%.2f' % v


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument('--max-error-m', type=float, default=1.0)
    ap.add_argument('paths', nargs='+')
    a = ap.parse_args()
    rows = [row(n, ev, dr, a.max_error_m) for p in a.paths for n, ev, dr in evaluations(p)]
    print('| evaluation | closures | without measured pose | false (> %g m) | largest error [m] '
          '| largest yaw error [deg] |' % a.max_error_m)
    print('|---|---|---|---|---|---|')
    for name, n, unknown, false, worst, worst_yaw in rows:
        print('| %s | %d | %d | %d | %s | %s |'
              % (name, n, unknown, false, fmt(worst), fmt(worst_yaw)))
    total = lambda i: sum(r[i] for r in rows)
    worst = max((r[4] for r in rows if r[4] is not None), default=None)
    worst_yaw = max((r[5] for r in rows if r[5] is not None), default=None)
    print('| **all %d** | %d | %d | **%d** | %s | %s |'
          % (len(rows), total(1), total(2), total(3), fmt(worst), fmt(worst_yaw)))


if __name__ == '__main__':
    main()
