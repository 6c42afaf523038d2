"""Which poses of a drive lie on a SUMO edge's first traversal (DRIVE/pose_edges.csv), for the
bench scripts that tell the streets as first driven apart from mapped streets driven again."""
import bisect
import csv
import sys


class FirstPasses:
    """Reads DRIVE_DIR/pose_edges.csv; `at(t)` is True on an edge's first traversal (a later
    traversal starts when the drive comes back onto an edge it has left)."""

    def __init__(self, drive_dir, script):
        path = drive_dir + "/pose_edges.csv"
        try:
            with open(path) as f:
                rows = [(float(r["t"]), r["sumo_edge"]) for r in csv.DictReader(f)]
        except (OSError, KeyError, TypeError, ValueError) as e:
            sys.exit("%s: %s: %s" % (script, path, e))
        if not rows:
            sys.exit("%s: %s: no poses" % (script, path))
        self.times = [t for t, _ in rows]
        self.first, seen, prev, fresh = [], set(), None, True
        for _, edge in rows:
            if edge != prev:
                fresh, prev = edge not in seen, edge
                seen.add(edge)
            self.first.append(fresh)

    def at(self, t):
        i = bisect.bisect_left(self.times, t - 1e-6)
        return self.first[min(i, len(self.first) - 1)]
