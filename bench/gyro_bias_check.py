#!/usr/bin/env python3
"""The gyro bias of a drive, measured against its ground truth, beside what `slamroute evaluate`
estimated from the drive's stops (metrics.json gyro_bias_deg_s). True bias = mean of (gyro
yaw rate - ground-truth yaw rate over the same 0.1 s interval) over the whole drive. Also the
naive standstill mean (wheel speed < 0.15 m/s, no margin), which the ground truth's heading
turning in the last 0.5 s of a stop spoils. Usage: bench/gyro_bias_check.py DRIVE_DIR
[EVAL_DIR]. Prints Markdown. Python 3 standard library only.
"""
import bisect, csv, json, math, os, sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from script_help import exit_on_help  # noqa: E402


def main():
    exit_on_help(__doc__)
    if len(sys.argv) not in (2, 3):
        sys.exit('usage: bench/gyro_bias_check.py DRIVE_DIR [EVAL_DIR]')
    drive = sys.argv[1]
    ev = sys.argv[2] if len(sys.argv) > 2 else None
    gt = [list(map(float, l.split())) for l in open(os.path.join(drive, 'groundtruth.tum'))
          if l.strip() and not l.startswith('#')]
    t_gt = [r[0] for r in gt]
    yaw = []
    for r in gt:
        x, y, z, w = r[4:8]
        yaw.append(math.atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z)))
    diffs, still = [], []
    with open(os.path.join(drive, 'odometry.csv')) as f:
        for row in csv.DictReader(f):
            t = float(row['t'])
            i = bisect.bisect_left(t_gt, t - 1e-6)
            if i + 1 >= len(gt) or abs(t_gt[i] - t) > 1e-3:
                continue
            d = math.remainder(yaw[i + 1] - yaw[i], 2 * math.pi) / (t_gt[i + 1] - t_gt[i])
            g = float(row['yaw_rate_rad_s'])
            diffs.append(g - d)
            if abs(float(row['speed_mps'])) < 0.15:
                still.append(g)
    deg = 180 / math.pi
    print('| drive | samples | true bias [deg/s] | naive standstill mean [deg/s] | evaluate estimate [deg/s] |')
    print('|---|---|---|---|---|')
    est = '-'
    if ev and os.path.exists(os.path.join(ev, 'metrics.json')):
        m = json.load(open(os.path.join(ev, 'metrics.json')))
        if 'gyro_bias_deg_s' in m:
            est = '%.4f (from %.0f s)' % (m['gyro_bias_deg_s'], m.get('gyro_standstill_s', 0))
    naive = '%.4f' % (deg * sum(still) / len(still)) if still else '-'
    print('| %s | %d | %.4f | %s | %s |' % (drive, len(diffs), deg * sum(diffs) / max(1, len(diffs)), naive, est))


if __name__ == '__main__':
    main()
