#!/usr/bin/python3
"""Candidate roundabout rings of a survey and the figures of the ring test, for the diagnosis in
bench/RESULTS.md ("Road graph: node and edge accuracy"). An independent re-implementation of roadgraph/src/Roundabouts.cpp
steps 1-3 with its default parameters, which prints every candidate ring (>= 3 vehicles circling
one centre), not only the accepted ones.

usage: bench/roundabout_rings.py SURVEY/traces.csv
Columns: centre, radius, vehicles, sectors of 36 holding >= 3 points moving along the ring, share of
those points circling in the majority sense, points inside half the radius / points on the ring,
and the verdict with the defaults (>= 33 sectors, >= 0.9 one sense, <= 0.02 inside).
Needs numpy (/usr/bin/python3 on Debian: python3-numpy).
"""
import csv
import math
import os
import sys
from collections import defaultdict

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from script_help import exit_on_help  # noqa: E402

import numpy as np

STEP, WINDOWS_M = 2.0, (20.0, 32.0, 48.0, 64.0)
MIN_R, MAX_R, MAX_RMS, MIN_SWEEP = 6.0, 30.0, 0.8, math.radians(120.0)
CENTRE_TOL, MIN_VEH, BAND, SPAN_M, MAX_GAP_S = 6.0, 3, 3.5, 5.0, 3.0


def read(path):
    by_vehicle = defaultdict(list)
    with open(path) as f:
        rows = csv.reader(f)
        head = next(rows)
        it, iv, ix, iy = (head.index(k) for k in ("t", "vehicle", "x", "y"))
        for r in rows:
            by_vehicle[r[iv]].append((float(r[it]), float(r[ix]), float(r[iy])))
    return {v: sorted(p) for v, p in sorted(by_vehicle.items())}


def runs_of(pts):
    """The vehicle's path split at time gaps, each averaged over STEP metres of travel."""
    out, cur, acc, travelled = [], [], [], 0.0
    for k, (t, x, y) in enumerate(pts):
        if k and t - pts[k - 1][0] > MAX_GAP_S:
            if len(cur) >= 6:
                out.append(np.array(cur))
            cur, acc, travelled = [], [], 0.0
        elif k:
            travelled += math.hypot(x - pts[k - 1][1], y - pts[k - 1][2])
        acc.append((x, y))
        if travelled >= STEP:
            cur.append(np.mean(acc, axis=0))
            acc, travelled = [], 0.0
    if len(cur) >= 6:
        out.append(np.array(cur))
    return out


def fit(P):
    m = P.mean(axis=0)
    Q = P - m
    A = np.c_[Q, np.ones(len(Q))]
    sol, *_ = np.linalg.lstsq(A, -(Q ** 2).sum(axis=1), rcond=None)
    c = np.array([-sol[0] / 2, -sol[1] / 2])
    r2 = c @ c - sol[2]
    if not MIN_R ** 2 <= r2 <= MAX_R ** 2:
        return None
    r = math.sqrt(r2)
    if math.sqrt(((np.linalg.norm(Q - c, axis=1) - r) ** 2).mean()) > MAX_RMS:
        return None
    u, v = Q[:-1] - c, Q[1:] - c
    da = np.arctan2(u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0], (u * v).sum(axis=1))
    if not (np.all(da > 0) or np.all(da < 0)) or abs(da.sum()) < MIN_SWEEP:
        return None
    return c + m, r


def circling_stretches(traces):
    out = []  # (cx, cy, r, vehicle)
    for w in WINDOWS_M:
        n = int(round(w / STEP))
        for veh, pts in traces.items():
            for S in runs_of(pts):
                i = 0
                while i + n <= len(S):
                    f = fit(S[i:i + n])
                    if f:
                        out.append((f[0][0], f[0][1], f[1], veh))
                    i += max(1, n // 2) if f else 2
    return out


def rings(stretches):
    C = np.array([(x, y) for x, y, _, _ in stretches])
    dens = [(-(np.hypot(*(C - C[i]).T) <= CENTRE_TOL).sum(), i) for i in range(len(C))]
    used = np.zeros(len(C), bool)
    out = []
    for _, seed in sorted(dens):
        if used[seed]:
            continue
        near = lambda c: (~used) & (np.hypot(*(C - c).T) <= CENTRE_TOL)
        m = near(C[seed])
        centre = np.median(C[m], axis=0)
        m = near(centre)
        m[seed] = True
        used |= m
        vehicles = {stretches[k][3] for k in np.flatnonzero(m)}
        if len(vehicles) >= MIN_VEH:
            r = float(np.median([stretches[k][2] for k in np.flatnonzero(m)]))
            out.append((centre, r, len(vehicles)))
    return out


def directions(traces):
    """Per point: position and unit direction of travel over +-SPAN_M along its own trace."""
    P, D = [], []
    for pts in traces.values():
        a = np.array([(x, y) for _, x, y in pts])
        cum = np.r_[0.0, np.cumsum(np.hypot(*np.diff(a, axis=0).T))]
        ahead = np.minimum(np.searchsorted(cum, cum + SPAN_M), len(a) - 1)
        behind = np.maximum(np.searchsorted(cum, cum - SPAN_M, side="right") - 1, 0)
        d = a[ahead] - a[behind]
        L = np.linalg.norm(d, axis=1)
        d[L < SPAN_M] = 0.0
        P.append(a)
        D.append(d / np.maximum(L, 1e-9)[:, None])
    return np.vstack(P), np.vstack(D)


def main():
    exit_on_help(__doc__)
    if len(sys.argv) != 2:
        sys.exit("usage: bench/roundabout_rings.py SURVEY/traces.csv")
    traces = read(sys.argv[1])
    cands = rings(circling_stretches(traces))
    P, D = directions(traces)
    print("centre_x centre_y radius_m vehicles sectors one_sense inside verdict")
    for centre, r, nveh in sorted(cands, key=lambda c: -c[2]):
        v = P - centre
        d = np.hypot(*v.T)
        on = np.abs(d - r) <= BAND
        rad = v[on] / np.maximum(d[on], 1e-9)[:, None]
        t = D[on]
        moving = np.linalg.norm(t, axis=1) > 0.5
        along = moving & (np.abs((rad * t).sum(axis=1)) < 0.5)
        cross = rad[:, 0] * t[:, 1] - rad[:, 1] * t[:, 0]
        ccw = (cross[along] > 0).mean() if along.any() else 0.0
        sense = max(ccw, 1 - ccw)
        ang = np.arctan2(rad[along, 1], rad[along, 0])
        sectors = (np.bincount(((ang + math.pi) / (2 * math.pi) * 36).astype(int).clip(0, 35),
                               minlength=36) >= 3).sum()
        inside = (d < 0.5 * r).sum() / max(on.sum(), 1)
        ok = sectors >= 0.9 * 36 and sense >= 0.9 and inside <= 0.02
        print("%.0f %.0f %.1f %d %d %.2f %.3f %s" % (centre[0], centre[1], r, nveh, sectors, sense,
                                                     inside, "ring" if ok else "-"))


if __name__ == "__main__":
    main()
