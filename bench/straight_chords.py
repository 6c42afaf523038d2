#!/usr/bin/env python3
"""How long the estimate makes the straight stretches of a drive against the ground truth
(docs/NOTES.md "What the whole-city ATE is made of"): over windows of up to 2 s on which the
true heading turns less than 1 deg and the car moves more than 8 m, the sum of the estimate's
chords over the truth's, for north-south and east-west stretches and per street (stretches
grouped by their x (north-south) or y (east-west) rounded to 25 m; streets with >= 150 m shown),
and per direction the median of the windows' estimate chord less the true one (one bad
registration moves a sum over a few hundred metres; the median stays). A ratio below 1 is a
shortfall along the streets. Usage: bench/straight_chords.py DRIVE_DIR EVAL_DIR. Needs numpy and
scipy (Debian python3-numpy, python3-scipy).
"""
import os
import signal
import sys
from collections import defaultdict

import numpy as np
from scipy.spatial.transform import Rotation as R

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from script_help import exit_on_help  # noqa: E402
from tum import load_tum  # noqa: E402


def stretches(drive, ev):
    """(key, estimate chord, true chord) per straight window."""
    gt = load_tum(drive + "/groundtruth.tum", "straight_chords.py")
    es = load_tum(ev + "/estimate.tum", "straight_chords.py")
    truth = {round(r[0], 1): r for r in gt}
    rows = [r for r in es if round(r[0], 1) in truth]
    E = np.array(rows)
    T = np.array([truth[round(r[0], 1)] for r in rows])
    yaw = np.unwrap(R.from_quat(T[:, 4:8]).as_euler("zyx")[:, 0])
    i, n = 0, len(E)
    while i < n:
        j = i
        while j + 1 < n and E[j + 1, 0] - E[i, 0] <= 2.0:
            j += 1
        dg, de = T[j, 1:3] - T[i, 1:3], E[j, 1:3] - E[i, 1:3]
        if j > i and np.linalg.norm(dg) > 8 and np.ptp(yaw[i:j + 1]) < np.radians(1):
            ns = abs(dg[1]) > abs(dg[0])
            street = "NS x=%d" % (round(T[i, 1] / 25) * 25) if ns else "EW y=%d" % (round(T[i, 2] / 25) * 25)
            yield ("NS" if ns else "EW"), street, np.linalg.norm(de), np.linalg.norm(dg)
        i = j + 1 if j > i else i + 1


def main():
    signal.signal(signal.SIGPIPE, signal.SIG_DFL)  # `| head` ends it quietly
    exit_on_help(__doc__)
    if len(sys.argv) != 3:
        sys.exit("usage: bench/straight_chords.py DRIVE_DIR EVAL_DIR")
    by_dir, by_street = defaultdict(lambda: [0.0, 0.0]), defaultdict(lambda: [0.0, 0.0])
    windows = defaultdict(list)
    for d, street, e, g in stretches(sys.argv[1], sys.argv[2]):
        windows[d].append(e - g)
        for acc, k in ((by_dir, d), (by_street, street)):
            acc[k][0] += e
            acc[k][1] += g
    for k, (e, g) in sorted(by_dir.items()):
        print("%s: estimate / truth %.5f over %.0f m; median window %+.1f mm of %d" %
              (k, e / g, g, 1000 * np.median(windows[k]), len(windows[k])))
    for k, (e, g) in sorted(by_street.items()):
        if g >= 150:
            print("  %s: %.5f over %.0f m" % (k, e / g, g))


if __name__ == "__main__":
    main()
