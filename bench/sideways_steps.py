#!/usr/bin/env python3
"""Steps of a drive's ground truth that move across the vehicle's heading (docs/NOTES.md,
"Sideways jumps in SUMO's junctions"): no car crabs, and no wheel odometry or gyro would see it
if one did, so a recorded path should have none. Per drive folder: how many 0.1 s steps move
faster than --speed (m/s, default 3) across the heading halfway between their two poses, the
metres they move across in all, and the largest, with its time (and SUMO edge from
pose_edges.csv when the folder has one).
Usage: bench/sideways_steps.py [--speed V] DRIVE_DIR...
Needs numpy and scipy (Debian python3-numpy, python3-scipy).
"""
import csv
import os
import sys

import numpy as np
from scipy.spatial.transform import Rotation as R

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from script_help import exit_on_help  # noqa: E402
from tum import load_tum  # noqa: E402

USAGE = 'usage: bench/sideways_steps.py [--speed V] DRIVE_DIR...'
NAME = 'sideways_steps.py'
exit_on_help(__doc__)
args = sys.argv[1:]
speed = 3.0
if args[:1] == ['--speed']:
    try:
        speed = float(args[1])
    except (IndexError, ValueError):
        sys.exit(USAGE)
    if not speed > 0:
        sys.exit(NAME + ': --speed must be a positive number of m/s')
    args = args[2:]
if not args:
    sys.exit(USAGE)


def edges_by_time(folder):
    path = os.path.join(folder, 'pose_edges.csv')
    if not os.path.isfile(path):
        return {}
    with open(path, newline='') as f:
        return {round(float(r['t']), 1): r['sumo_edge'] for r in csv.DictReader(f)}


for folder in args:
    g = load_tum(os.path.join(folder, 'groundtruth.tum'), NAME)
    yaw = R.from_quat(g[:, 4:8]).as_euler('ZYX')[:, 0]
    mid = yaw[:-1] + 0.5 * np.remainder(yaw[1:] - yaw[:-1] + np.pi, 2 * np.pi) - 0.5 * np.pi
    step = np.diff(g[:, 1:3], axis=0)
    dt = np.maximum(np.diff(g[:, 0]), 1e-9)
    across = -step[:, 0] * np.sin(mid) + step[:, 1] * np.cos(mid)
    fast = np.abs(across) / dt > speed
    line = '%s: %d steps over %.1f m/s across the heading, %.2f m across in them' % (
        folder, fast.sum(), speed, np.abs(across[fast]).sum())
    k = int(np.argmax(np.abs(across)))
    edge = edges_by_time(folder).get(round(g[k, 0], 1))
    line += '; largest %.2f m in %.1f s at t %.1f s%s' % (
        abs(across[k]), dt[k], g[k, 0], ' on ' + edge if edge else '')
    print(line)
