#!/usr/bin/env python3
"""How many survey vehicles drove each road into a SUMO junction (bench/RESULTS.md, "Node F1 on
nets not used for tuning": why a missed junction is missed).

Usage: bench/junction_coverage.py NET.net.xml SURVEY_DIR JUNCTION [JUNCTION ...]

For every passenger edge into or out of each junction: its length and the number of distinct
vehicles of SURVEY_DIR/traces.csv with a trace point within 4 m of the middle of its first
passenger lane. Standard library only.
"""
import csv
import math
import os
import sys
import xml.etree.ElementTree as ET
from collections import defaultdict

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from script_help import exit_on_help  # noqa: E402

RADIUS_M = 4.0


def passenger(lane):
    allow, disallow = lane.get("allow"), lane.get("disallow") or ""
    return ("passenger" in allow.split() or "all" in allow.split()) if allow else "passenger" not in disallow.split()


def middle(shape):
    pts = [tuple(map(float, p.split(","))) for p in shape.split()]
    half = sum(math.dist(a, b) for a, b in zip(pts, pts[1:])) / 2
    for a, b in zip(pts, pts[1:]):
        d = math.dist(a, b)
        if d >= half and d > 0:
            return (a[0] + (b[0] - a[0]) * half / d, a[1] + (b[1] - a[1]) * half / d)
        half -= d
    return pts[-1]


def main():
    exit_on_help(__doc__)
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    net, survey, ids = sys.argv[1], sys.argv[2], set(sys.argv[3:])
    traces = os.path.join(survey, "traces.csv")
    for path in (net, traces):
        if not os.path.isfile(path):
            sys.exit(f"junction_coverage.py: {path}: no such file")
    cells = defaultdict(list)  # 4 m grid cell -> (x, y, vehicle)
    with open(traces) as f:
        for row in csv.DictReader(f):
            x, y = float(row["x"]), float(row["y"])
            cells[(int(x // RADIUS_M), int(y // RADIUS_M))].append((x, y, row["vehicle"]))
    for edge in ET.parse(net).getroot().iter("edge"):
        if edge.get("function") == "internal" or not ({edge.get("from"), edge.get("to")} & ids):
            continue
        lanes = [lane for lane in edge.iter("lane") if passenger(lane)]
        if not lanes:
            continue
        mx, my = middle(lanes[0].get("shape"))
        cx, cy = int(mx // RADIUS_M), int(my // RADIUS_M)
        vehicles = {v for dx in (-1, 0, 1) for dy in (-1, 0, 1) for x, y, v in cells.get((cx + dx, cy + dy), ())
                    if math.dist((x, y), (mx, my)) <= RADIUS_M}
        print(f"{edge.get('from')} -> {edge.get('to')}: {float(lanes[0].get('length')):.1f} m, "
              f"{len(vehicles)} vehicles")


if __name__ == "__main__":
    main()
