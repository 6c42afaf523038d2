#!/usr/bin/env python3
"""Checks the shipped networks with SUMO's own tools (sumolib, sumo, randomTrips.py).

    python3 networks/check.py              # counts + geometry checks of every shipped net
    python3 networks/check.py --simulate   # also: sumo loads each net, random trips drive on it

Prints, per net: junctions, passenger edges, largest strongly connected part (edge level, with
SUMO's <connection>s as the turn rules), street length, the closest pair of junctions, and for
nets with elevated roads the max z of lane shapes. Exits non-zero when a check fails.
"""
import math
import os
import subprocess
import sys
import tempfile

SUMO_HOME = os.environ.setdefault("SUMO_HOME", "/usr/share/sumo")
sys.path.insert(0, os.path.join(SUMO_HOME, "tools"))
import sumolib  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
NETS = {
    "default_city": "default_city/default_city.net.xml",
    "plus": "test/plus.net.xml",
    "grid3x3": "test/grid3x3.net.xml",
    "stub": "test/stub.net.xml",
    "turning_place": "test/turning_place.net.xml",
    "ring": "test/ring.net.xml",
    "overpass": "test/overpass.net.xml",
    "divided_avenue": "test/divided_avenue.net.xml",
    "divided_cross": "test/divided_cross.net.xml",
}
DIVIDED = {"divided_avenue", "divided_cross"}
sys.path.insert(0, HERE)
sys.dont_write_bytecode = True  # keep networks/ free of __pycache__
import generate  # noqa: E402

# Crossing points of elevated roads, by construction (generate.py): ((x, y), deck z).
_rows = {r[0]: r for r in generate.ROWS}
_cols = {c[0]: c for c in generate.COLS}
CROSSINGS = {
    "overpass": [((500.0, 500.0), generate.OVERPASS_DECK_Z)],
    "default_city": [(generate.intersect(_rows[r], _cols[c]), generate.CITY_DECK_Z)
                     for r, c in sorted(generate.GRADE_SEPARATED)],
}


def largest_scc(edges, succ):
    """Tarjan (iterative) on edges; succ[e] = successor edges. Returns the largest SCC."""
    index, low, on, stack, best = {}, {}, set(), [], []
    counter = [0]
    for root in edges:
        if root in index:
            continue
        work = [(root, iter(succ[root]))]
        index[root] = low[root] = counter[0]
        counter[0] += 1
        stack.append(root)
        on.add(root)
        while work:
            v, it = work[-1]
            advanced = False
            for w in it:
                if w not in index:
                    index[w] = low[w] = counter[0]
                    counter[0] += 1
                    stack.append(w)
                    on.add(w)
                    work.append((w, iter(succ[w])))
                    advanced = True
                    break
                if w in on:
                    low[v] = min(low[v], index[w])
            if advanced:
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[v])
            if low[v] == index[v]:
                comp = []
                while True:
                    w = stack.pop()
                    on.discard(w)
                    comp.append(w)
                    if w == v:
                        break
                if len(comp) > len(best):
                    best = comp
    return best


def seg_intersection(p, q, r, s):
    """2D intersection point of segments p-q and r-s, or None."""
    d = (q[0] - p[0]) * (s[1] - r[1]) - (q[1] - p[1]) * (s[0] - r[0])
    if abs(d) < 1e-12:
        return None
    t = ((r[0] - p[0]) * (s[1] - r[1]) - (r[1] - p[1]) * (s[0] - r[0])) / d
    u = ((r[0] - p[0]) * (q[1] - p[1]) - (r[1] - p[1]) * (q[0] - p[0])) / d
    if 0 < t < 1 and 0 < u < 1:
        return (p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1]))
    return None


def z_at(shape, xy):
    """z of the 3D polyline point closest (in 2D) to xy."""
    best = (1e18, 0.0)
    for a, b in zip(shape, shape[1:]):
        ax, ay, az = (a + (0.0,))[:3]
        bx, by, bz = (b + (0.0,))[:3]
        L2 = (bx - ax) ** 2 + (by - ay) ** 2
        t = 0.0 if L2 == 0 else max(0.0, min(1.0, ((xy[0] - ax) * (bx - ax) + (xy[1] - ay) * (by - ay)) / L2))
        px, py = ax + t * (bx - ax), ay + t * (by - ay)
        d = math.hypot(px - xy[0], py - xy[1])
        if d < best[0]:
            best = (d, az + t * (bz - az))
    return best[1]


def check_net(name, rel, failures):
    path = os.path.join(HERE, rel)
    net = sumolib.net.readNet(path, withInternal=False, withPedestrianConnections=False)
    junctions = [n for n in net.getNodes() if n.getType() != "internal"]
    pedges = [e for e in net.getEdges() if e.getFunction() == "" and e.allows("passenger")]
    pset = set(e.getID() for e in pedges)
    succ = {e.getID(): sorted(set(t.getID() for t, conns in e.getOutgoing().items()
                                  if t.getID() in pset and any(c.getFromLane().allows("passenger")
                                                                for c in conns)))
            for e in pedges}
    scc = largest_scc([e.getID() for e in pedges], succ)
    total = sum(e.getLength() for e in pedges)
    scc_len = sum(net.getEdge(e).getLength() for e in scc)
    # undirected street length: a two-way street counted once
    streets = {}
    for e in pedges:
        key = tuple(sorted((e.getFromNode().getID(), e.getToNode().getID())))
        streets[key] = max(streets.get(key, 0.0), e.getLength())
    one_way = sum(1 for e in pedges
                  if not any(o.getToNode() == e.getFromNode() for o in e.getToNode().getOutgoing()
                             if o.getID() in pset))
    # closest pair of junctions with degree >= 3 (real intersections) and of any junctions
    real = [n for n in junctions
            if len(set(x.getID() for x in n.getNeighboringNodes())) >= 3]
    def closest(nodes):
        best = (1e18, None, None)
        for i, a in enumerate(nodes):
            for b in nodes[i + 1:]:
                d = math.dist(a.getCoord()[:2], b.getCoord()[:2])
                if d < best[0]:
                    best = (d, a.getID(), b.getID())
        return best
    deg = {}
    for n in junctions:
        k = len(set(x.getID() for x in n.getNeighboringNodes()))
        deg[k] = deg.get(k, 0) + 1
    types = {}
    for n in junctions:
        types[n.getType()] = types.get(n.getType(), 0) + 1
    maxz = 0.0
    elevated = []
    for e in pedges:
        for lane in e.getLanes():
            z = max((p[2] if len(p) > 2 else 0.0) for p in lane.getShape3D())
            if z > 0.5:
                elevated.append(e.getID())
            maxz = max(maxz, z)
    xmin, ymin, xmax, ymax = net.getBoundary()
    print("%s (%s)" % (name, rel))
    print("  junctions: %d  (by degree: %s; types: %s)" % (
        len(junctions), ", ".join("%d:%d" % kv for kv in sorted(deg.items())),
        ", ".join("%s:%d" % kv for kv in sorted(types.items()))))
    print("  passenger edges: %d (%d on one-way streets), streets: %d" % (len(pedges), one_way, len(streets)))
    print("  largest strongly connected part: %d edges (%.1f%%), %.0f m" % (
        len(scc), 100.0 * len(scc) / max(1, len(pedges)), scc_len))
    print("  passenger edge length: %.0f m; street length (two-way once): %.0f m" % (
        total, sum(streets.values())))
    print("  extent: %.0f x %.0f m" % (xmax - xmin, ymax - ymin))
    if len(real) >= 2:
        d, a, b = closest(real)
        print("  closest intersections (degree >= 3): %.1f m (%s, %s)" % (d, a, b))
        # The divided nets' carriageway crossings are close by design (one place per pair).
        if d < 35.0 and name not in DIVIDED:
            failures.append("%s: intersections %s and %s only %.1f m apart" % (name, a, b, d))
    d, a, b = closest(junctions)
    print("  closest junctions: %.1f m (%s, %s)" % (d, a, b))
    print("  max lane z: %.2f m; elevated edges: %s" % (maxz, sorted(set(elevated)) or "-"))
    # every 2D crossing of passenger edges that is not at a junction must be grade-separated
    shapes = {e.getID(): [p if len(p) > 2 else (p[0], p[1], 0.0) for p in e.getLane(0).getShape3D()]
              for e in pedges}
    ids = sorted(shapes)
    found = []
    for i, a in enumerate(ids):
        ea = net.getEdge(a)
        for b in ids[i + 1:]:
            eb = net.getEdge(b)
            if {ea.getFromNode(), ea.getToNode()} & {eb.getFromNode(), eb.getToNode()}:
                continue
            for p, q in zip(shapes[a], shapes[a][1:]):
                for r, s in zip(shapes[b], shapes[b][1:]):
                    x = seg_intersection(p, q, r, s)
                    if x:
                        found.append((a, b, x, z_at(shapes[a], x), z_at(shapes[b], x)))
    for a, b, x, za, zb in found:
        near = min(math.dist(n.getCoord()[:2], x) for n in junctions)
        print("  crossing without junction: %s (z %.2f) x %s (z %.2f) at (%.1f, %.1f); nearest "
              "junction %.0f m" % (a, za, b, zb, x[0], x[1], near))
        if abs(za - zb) < 4.0:
            failures.append("%s: %s and %s cross at grade without a junction" % (name, a, b))
        if near < 35.0:
            failures.append("%s: junction within 35 m of the crossing at %s" % (name, x))
    for xy, deck_z in CROSSINGS.get(name, []):
        if not any(math.dist(x, xy) < 8.0 and abs(max(za, zb) - deck_z) < 0.3 and min(za, zb) < 0.3
                   for _, _, x, za, zb in found):
            failures.append("%s: expected a crossing with a %.1f m deck at %s" % (name, deck_z, xy))
    if len(scc) < 0.9 * len(pedges):
        failures.append("%s: largest strongly connected part holds only %d of %d edges"
                        % (name, len(scc), len(pedges)))
    return net


def run(cmd, cwd=None):
    r = subprocess.run(cmd, capture_output=True, text=True, cwd=cwd)
    out = r.stdout + r.stderr
    if r.returncode != 0:
        raise RuntimeError("%s failed (%d):\n%s" % (" ".join(cmd), r.returncode, out))
    return out


def simulate(name, rel, failures):
    path = os.path.join(HERE, rel)
    with tempfile.TemporaryDirectory() as tmp:
        try:
            out = run(["sumo", "-n", path, "--end", "10", "--no-step-log"])
            bad = [l for l in out.splitlines() if "Error" in l]
            trips = os.path.join(tmp, "x.trips.xml")
            run([sys.executable, os.path.join(SUMO_HOME, "tools", "randomTrips.py"), "-n", path,
                 "-o", trips, "-e", "100", "--seed", "42", "--validate"], cwd=tmp)
            ntrips = open(trips).read().count("<trip ")
            out = run(["sumo", "-n", path, "-r", trips, "--end", "300", "--no-step-log",
                       "--duration-log.statistics"])
            bad += [l for l in out.splitlines() if "Error" in l]
            teleports = [l for l in out.splitlines() if "Teleporting" in l]
            ins = [l.strip() for l in out.splitlines() if "Inserted:" in l or "Statistics" in l
                   or "RouteLength" in l]
            print("  sumo: %d trips, %s; teleports: %d%s" % (
                ntrips, "; ".join(ins[:3]), len(teleports),
                "; errors: " + " | ".join(bad) if bad else ""))
            if bad:
                failures.append("%s: sumo reported errors" % name)
        except RuntimeError as e:
            failures.append("%s: %s" % (name, e))


def main():
    failures = []
    for name, rel in NETS.items():
        check_net(name, rel, failures)
        if "--simulate" in sys.argv:
            simulate(name, rel, failures)
    if failures:
        print("FAILED:\n  " + "\n  ".join(failures))
        sys.exit(1)
    print("all checks passed")


if __name__ == "__main__":
    main()
