#!/usr/bin/env python3
"""Per drive of an `experiment paper` / `run` folder: ATE, RPE, loop closures and how many of
them are false, largest raw error, drift per street kind. A closure is false when the relative
pose the ICP measured between the two keyframes is more than 2 m off the ground truth's (for
metrics.json files without the measured pose: when the keyframes are > 8 m apart in the ground
truth). Usage: bench/loop_closure_check.py OUT_DIR (with drives/ and eval/), or
bench/loop_closure_check.py DRIVE_DIR EVAL_DIR. Prints Markdown. Python 3 standard library only.
"""
import bisect, glob, json, math, os, sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from script_help import exit_on_help  # noqa: E402


def tum(p):
    return [list(map(float, l.split())) for l in open(p) if l.strip() and not l.startswith('#')]


def rot(q):  # qx qy qz qw -> 3x3 rows
    x, y, z, w = q
    return [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
            [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
            [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]]


def relative(a, b):  # translation of b in a's frame (TUM rows)
    R = rot(a[4:8])
    d = [b[i] - a[i] for i in (1, 2, 3)]
    return [sum(R[r][c] * d[r] for r in range(3)) for c in range(3)]


def relative_yaw_deg(a, b):  # yaw of b in a's frame (TUM rows)
    Ra, Rb = rot(a[4:8]), rot(b[4:8])
    m00 = sum(Ra[k][0] * Rb[k][0] for k in range(3))
    m10 = sum(Ra[k][1] * Rb[k][0] for k in range(3))
    return math.degrees(math.atan2(m10, m00))


def ground_truth_at(dr):  # t -> the drive's first ground-truth row at or after t
    gt = tum(dr + '/groundtruth.tum')
    ts = [x[0] for x in gt]
    return lambda t: gt[min(bisect.bisect_left(ts, t - 1e-6), len(gt) - 1)]


def closure_errors(at, loops):
    """Per accepted closure: (translation error [m], yaw error [deg]) of the relative pose it
    measured against the ground truth's; (None, None) for metrics.json without the measured pose."""
    out = []
    for L in loops:
        a, b = at(L['t_old']), at(L['t_new'])
        if 't_old_new' not in L:
            out.append((None, None))
            continue
        yaw = L.get('yaw_old_new_deg')
        dyaw = None if yaw is None else abs((yaw - relative_yaw_deg(a, b) + 180) % 360 - 180)
        out.append((math.dist(relative(a, b), L['t_old_new']), dyaw))
    return out


def check(dr, ev, name):
    m = json.load(open(ev + '/metrics.json'))
    at = ground_truth_at(dr)
    bad, errs = 0, []
    for L, (err, _) in zip(m['loops'], closure_errors(at, m['loops'])):
        if err is not None:
            errs.append(err)
            bad += err > 2.0
        else:
            a, b = at(L['t_old']), at(L['t_new'])
            bad += math.dist(a[1:3], b[1:3]) > 8
    est = tum(ev + '/estimate.tum')
    mx = max((math.dist(e[1:3], at(e[0])[1:3]) for e in est[::20]), default=0)
    d = m.get('drift_by_label', {})
    errs.sort()
    med = '%.2f' % errs[len(errs) // 2] if errs else '-'
    return (name, m['evaluated_length_m'] / 1000, m['ate_rmse_m'], m['rpe_trans_pct'], m['loop_closures'], bad,
            med, mx,
            '/'.join('%.2f' % d[k]['drift_pct'] if k in d else '-' for k in ('rich', 'wall', 'open')))


def main():
    exit_on_help(__doc__)
    if len(sys.argv) not in (2, 3):
        sys.exit('usage: bench/loop_closure_check.py OUT_DIR | DRIVE_DIR EVAL_DIR')
    rows = []
    if len(sys.argv) == 3:
        rows.append(check(sys.argv[1], sys.argv[2], os.path.basename(sys.argv[2].rstrip('/'))))
    else:
        for ev in sorted(glob.glob(sys.argv[1] + '/eval/*')):
            name = os.path.basename(ev)
            if os.path.exists(ev + '/metrics.json'):
                rows.append(check(sys.argv[1] + '/drives/' + name, ev, name))
    print('| drive | km | ATE RMSE [m] | RPE [%] | loop closures | of them false | median loop error [m] '
          '| max raw error [m] | drift rich/wall/open [%] |')
    print('|---|---|---|---|---|---|---|---|---|')
    for r in rows:
        print('| %s | %.1f | %.2f | %.2f | %d | %d | %s | %.1f | %s |' % r)


if __name__ == '__main__':
    main()
