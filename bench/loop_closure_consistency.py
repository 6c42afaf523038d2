#!/usr/bin/env python3
"""Offline test of a loop-closure gate (docs/NOTES.md "Loop closures confirmed by a second
match"): for every accepted closure of the drives in an `experiment paper` / `run` folder, is it
false (its measured relative pose > 2 m off the ground truth's, as bench/loop_closure_check.py
counts) and does another closure within 15 s repeat its correction magnitude within 0.3 m?
Prints how many true and false closures such a neighbour would keep.
Usage: bench/loop_closure_consistency.py OUT_DIR [OUT_DIR ...]. Python 3 standard library only.
"""
import glob, json, math, os, sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from loop_closure_check import ground_truth_at, relative  # noqa: E402
from script_help import exit_on_help  # noqa: E402

exit_on_help(__doc__)
if len(sys.argv) < 2:
    sys.exit('usage: bench/loop_closure_consistency.py OUT_DIR [OUT_DIR ...]')

true_rows, false_rows = [], []
for root in sys.argv[1:]:
    for ev in sorted(glob.glob(root + '/eval/*')):
        if not os.path.exists(ev + '/metrics.json'):
            continue
        m = json.load(open(ev + '/metrics.json'))
        at = ground_truth_at(root + '/drives/' + os.path.basename(ev))
        loops = m['loops']
        for i, c in enumerate(loops):
            err = math.dist(relative(at(c['t_old']), at(c['t_new'])), c['t_old_new'])
            agreeing = sum(1 for j, d in enumerate(loops) if j != i and abs(d['t_new'] - c['t_new']) < 15
                           and abs(d['correction_m'] - c['correction_m']) < 0.3)
            (false_rows if err > 2.0 else true_rows).append((c['correction_m'], agreeing))


def kept(rows, pred):
    return sum(1 for r in rows if pred(r)), len(rows)


print('| rule | true closures kept | false closures kept |')
print('|---|---|---|')
for name, pred in [('an agreeing closure within 15 s', lambda r: r[1] > 0),
                   ('correction < 0.5 m or an agreeing closure', lambda r: r[0] < 0.5 or r[1] > 0)]:
    t, f = kept(true_rows, pred), kept(false_rows, pred)
    print('| %s | %d of %d (%.0f %%) | %d of %d (%.0f %%) |' % (
        name, t[0], t[1], 100.0 * t[0] / max(1, t[1]), f[0], f[1], 100.0 * f[0] / max(1, f[1])))
