#!/usr/bin/env python3
"""Where a drive's trajectory error lies (docs/NOTES.md "Corner features at grazing incidence"):
ATE RMSE after a rigid (Umeyama, no scale) alignment split into along-street, across-street and
height components (in the ground truth's heading), the ATE left after a fit with a scale
(Umeyama with scale: what a uniform shrink or stretch of the whole map accounts for), and the
per-scan relative-pose error summed separately over turns (|yaw rate| > 5 deg/s) and straight
stretches: a negative "along, straight" sum is a shortfall on the straights.
With --region X0,X1,Y0,Y1 (repeatable): the share of the poses and of the squared error inside
those boxes of the ground truth's x / y, the RMS inside and outside, and the ATE of the moving
poses alone (a long wait weighs the error where the car stands by the wait's length).
With --windows S: after those lines, where along the drive the rigid ATE is made, per window of
S seconds: its RMS, its share of the squared error and where the ground truth starts it, then
the window with the largest share (a false closure or a lost stretch shows up there).
With --passes: the RMS on the poses of each SUMO edge's first traversal (DRIVE/pose_edges.csv)
and on those of later ones. A route that drives mapped streets again adds poses of low error,
which lowers the ATE of the whole drive even where the streets as first driven are no better.
Usage: bench/trajectory_error_split.py [--windows S] [--region X0,X1,Y0,Y1 ...] [--passes]
DRIVE EVAL.
Needs numpy and scipy (Debian python3-numpy, python3-scipy).
"""
import os
import sys

import numpy as np
from scipy.spatial.transform import Rotation as R

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from first_passes import FirstPasses  # noqa: E402
from script_help import exit_on_help  # noqa: E402
from tum import load_tum  # noqa: E402

USAGE = ('usage: bench/trajectory_error_split.py [--windows S] [--region X0,X1,Y0,Y1 ...] '
         '[--passes] DRIVE_DIR EVAL_DIR')
NAME = 'trajectory_error_split.py'
exit_on_help(__doc__)
args = sys.argv[1:]
window_s = None
regions = []  # (x0, x1, y0, y1) in the ground truth's frame [m]
passes = '--passes' in args
args = [a for a in args if a != '--passes']
while args[:1] in (['--windows'], ['--region']):
    try:
        if args[0] == '--windows':
            window_s = float(args[1])
        else:
            regions.append([float(v) for v in args[1].split(',')])
    except (IndexError, ValueError):
        sys.exit(USAGE)
    if window_s is not None and not window_s > 0:
        sys.exit(NAME + ': --windows must be a positive number of seconds')
    if regions and len(regions[-1]) != 4:
        sys.exit(NAME + ': --region takes X0,X1,Y0,Y1 [m]')
    args = args[2:]
if len(args) != 2:
    sys.exit(USAGE)
gt = load_tum(args[0] + '/groundtruth.tum', NAME)
es = load_tum(args[1] + '/estimate.tum', NAME)
first_passes = FirstPasses(args[0], NAME) if passes else None
g = gt[[np.argmin(abs(gt[:, 0] - t)) for t in es[:, 0]]]

# Rigid alignment of the estimate's positions onto the ground truth's.
P, Q = es[:, 1:4], g[:, 1:4]
mp, mq = P.mean(0), Q.mean(0)
U, Sv, Vt = np.linalg.svd((P - mp).T @ (Q - mq))
D = np.eye(3)
D[2, 2] = np.sign(np.linalg.det(Vt.T @ U.T))
rot = Vt.T @ D @ U.T
d = (rot @ (P - mp).T).T + mq - Q
yaw = R.from_quat(g[:, 4:8]).as_euler('ZYX')[:, 0]
along = d[:, 0] * np.cos(yaw) + d[:, 1] * np.sin(yaw)
across = -d[:, 0] * np.sin(yaw) + d[:, 1] * np.cos(yaw)
rms = lambda x: np.sqrt((x ** 2).mean())
print('ATE RMSE %.3f m; RMS along %.3f, across %.3f, height %.3f m' %
      (np.sqrt((d ** 2).sum(1).mean()), rms(along), rms(across), rms(d[:, 2])))

# The same fit with a scale: s = trace(Sigma D) / var(P) (Umeyama 1991, eq. 42).
s = (Sv * np.diag(D)).sum() / ((P - mp) ** 2).sum()
ds = s * (rot @ (P - mp).T).T + mq - Q
print('with a scale: ATE RMSE %.3f m, scale %.5f' % (np.sqrt((ds ** 2).sum(1).mean()), s))


def poses(a):
    M = np.tile(np.eye(4), (len(a), 1, 1))
    M[:, :3, :3] = R.from_quat(a[:, 4:8]).as_matrix()
    M[:, :3, 3] = a[:, 1:4]
    return M


Te, Tg = poses(es), poses(g)
rows = []
for i in range(1, len(es)):
    de, dg = np.linalg.inv(Te[i - 1]) @ Te[i], np.linalg.inv(Tg[i - 1]) @ Tg[i]
    E = np.linalg.inv(dg) @ de
    rate = np.degrees(np.arctan2(dg[1, 0], dg[0, 0])) / max(es[i, 0] - es[i - 1, 0], 1e-6)
    rows.append((E[0, 3], E[1, 3], abs(rate) > 5.0))
rows = np.array(rows)
turn = rows[:, 2] > 0
print('relative-pose error sums: along turns %.3f, straight %.3f m; across turns %.3f, straight %.3f m'
      % (rows[turn, 0].sum(), rows[~turn, 0].sum(), rows[turn, 1].sum(), rows[~turn, 1].sum()))


def print_windows(t, sq, truth, width):
    print('where the rigid ATE is made, windows of %g s: start [s], RMS [m], share of the squared '
          'error, ground truth x y at the start' % width)
    best = None
    for start in np.arange(t[0], t[-1] + 1e-9, width):
        m = (t >= start) & (t < start + width)
        if not m.any():
            continue
        share = sq[m].sum() / max(sq.sum(), 1e-300)
        first = np.argmax(m)
        print('  %8.1f  %7.3f  %5.1f %%  %9.1f %9.1f' %
              (start, np.sqrt(sq[m].mean()), 100 * share, truth[first, 0], truth[first, 1]))
        if best is None or share > best[1]:
            best = (start, share)
    print('largest: the window from %.1f s, %.1f %% of the squared error' % (best[0], 100 * best[1]))


def masked_rms(sq, m):
    """RMS of the squared errors sq where the mask m holds (nan without any)."""
    return np.sqrt(sq[m].mean()) if m.any() else float('nan')


def print_regions(sq, truth, boxes):
    inside = np.zeros(len(sq), dtype=bool)
    for x0, x1, y0, y1 in boxes:
        inside |= (truth[:, 0] >= x0) & (truth[:, 0] <= x1) & (truth[:, 1] >= y0) & (truth[:, 1] <= y1)
    moving = np.r_[np.linalg.norm(np.diff(truth, axis=0), axis=1) > 0.05, True]
    print('regions: %.1f %% of the poses, %.1f %% of the squared error; RMS inside %.3f m, outside '
          '%.3f m; ATE of the moving poses %.3f m' %
          (100 * inside.mean(), 100 * sq[inside].sum() / max(sq.sum(), 1e-300),
           masked_rms(sq, inside), masked_rms(sq, ~inside), masked_rms(sq, moving)))


def print_passes(sq, first):
    print('first passes: RMS %.3f m on %.1f %% of the poses; later passes: RMS %.3f m' %
          (masked_rms(sq, first), 100 * first.mean(), masked_rms(sq, ~first)))


sq = (d ** 2).sum(1)
if window_s is not None:
    print_windows(es[:, 0], sq, g[:, 1:3], window_s)
if regions:
    print_regions(sq, g[:, 1:3], regions)
if passes:
    print_passes(sq, first_passes.mask(es[:, 0]))
