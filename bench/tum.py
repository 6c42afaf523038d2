"""Reads a TUM trajectory (t x y z qx qy qz qw per line, '#' comments) for the bench scripts,
ending the script with one line naming the file when it is missing, unreadable or malformed."""
import os
import sys

import numpy as np


def load_tum(path, script):
    if not os.path.isfile(path):
        sys.exit("%s: %s: no such file" % (script, path))
    try:
        rows = np.loadtxt(path, ndmin=2)
    except OSError as e:
        sys.exit("%s: %s: %s" % (script, path, e.strerror))
    except ValueError as e:
        sys.exit("%s: %s: not a TUM trajectory (%s)" % (script, path, str(e).splitlines()[0]))
    if rows.shape[0] < 2 or rows.shape[1] != 8:
        sys.exit("%s: %s: not a TUM trajectory (%d rows of %d columns; needs >= 2 rows of 8)" %
                 (script, path, rows.shape[0], rows.shape[1]))
    return rows
