"""Which poses of a drive lie on a SUMO edge's first traversal (DRIVE/pose_edges.csv), for the
bench scripts that tell the streets as first driven apart from mapped streets driven again."""
import csv
import sys

import numpy as np


class FirstPasses:
    """Reads DRIVE_DIR/pose_edges.csv; `mask(times)` is True on an edge's first traversal (a later
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
        self.times = np.array([t for t, _ in rows])
        first, seen, prev, fresh = [], set(), None, True
        for _, edge in rows:
            if edge != prev:
                fresh, prev = edge not in seen, edge
                seen.add(edge)
            first.append(fresh)
        self.first = np.array(first, dtype=bool)

    def mask(self, times):
        """A numpy bool array: True for the times on a first traversal (the pose at or after)."""
        i = np.searchsorted(self.times, np.asarray(times) - 1e-6)
        return self.first[np.minimum(i, len(self.first) - 1)]
