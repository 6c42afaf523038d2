#!/usr/bin/env python3
"""Why build-graph misses true streets (bench/RESULTS.md, "Divided roads").

Usage: bench/missed_edges.py NET.net.xml GRAPH.json [--link M] [--radius M] [--traces CSV]

Rebuilds the place-level scoring of build-graph's `place_validation` (roadgraph/src/SumoMatch.cpp:
on the net and on the graph alike, intersections (>= 3 neighbours) joined by a street (through
junctions with 2 neighbours) whose ends lie at most --link m apart are one place; true intersections have >= 3 neighbouring places; a true
street is a chain through places with 2 neighbours), matches the graph's places to the true ones
(closest pairs first, within --radius m) and prints the totals (to check against graph.json) and
one line per missed chain: its end places, the node matched to each (the lowest of its place),
its length along SUMO, and why it is missed:
  end node not detected   a chain end has no node; "tolerance" when an unmatched node lies
                          within 2 x radius of the place (it is there but placed too far)
  edge split              the streets along the chain meet at a node that is not a true place
                          (a second node of a place whose junctions lie apart: "its place
                          matched by node N")
  geometry mismatch       a street along the chain ends at another true place's node
  no street               no street of the graph runs along the chain (not driven, or cleared)
A street runs along a chain when most of its polyline lies within ALONG_M of the chain's SUMO
lanes (both carriageways). With --traces (the survey's traces.csv) each chain is also marked
driven or not (a trace point within DRIVEN_M of most of its lanes' samples, DRIVEN_SKIP_M off
its ends, and at least three arms of each end place driven, or the place is no junction in the
traces), and the recall over the driven chains alone is printed: the scoring counts every true
chain of the net, driven or not. Needs sumolib (Debian sumo-tools: $SUMO_HOME/tools).
"""
import argparse
import json
import math
import os
import sys
from collections import defaultdict

sys.path.insert(0, os.path.join(os.environ.get("SUMO_HOME", "/usr/share/sumo"), "tools"))
import sumolib  # noqa: E402

ALONG_M = 9.0          # a street point this close to the chain's lanes runs along it
ALONG_SHARE = 0.6      # share of a street's points that must run along the chain
STEP_M = 2.0
DRIVEN_M = 4.0         # a lane sample with a trace point this close was driven
DRIVEN_SKIP_M = 15.0   # ... not counting the samples this close to the chain's end places
DRIVEN_SHARE = 0.8     # share of a chain's samples that must be driven
ARM_SHARE = 0.4        # ... and of an arm's (one carriageway of two suffices)


def samples(shape, step=STEP_M):
    out = []
    for (ax, ay), (bx, by) in zip(shape, shape[1:]):
        n = max(1, int(math.hypot(bx - ax, by - ay) / step))
        out += [(ax + (bx - ax) * k / n, ay + (by - ay) * k / n) for k in range(n)]
    return out + shape[-1:]


class Grid:
    def __init__(self, pts, cell=ALONG_M):
        self.cell, self.cells = cell, defaultdict(list)
        for p in pts:
            self.cells[(int(p[0] // cell), int(p[1] // cell))].append(p)

    def near(self, p, r):
        cx, cy = int(p[0] // self.cell), int(p[1] // self.cell)
        return any(math.dist(p, q) <= r for i in (-1, 0, 1) for j in (-1, 0, 1)
                   for q in self.cells.get((cx + i, cy + j), ()))


def chain_end(nb, v, w):
    """The vertex reached from v through w and on through vertices with 2 neighbours."""
    prev, cur = v, w
    for _ in range(len(nb)):
        if len(nb[cur]) != 2:
            break
        a, b = sorted(nb[cur], key=str)
        prev, cur = cur, (b if a == prev else a)
    return cur


def group(pos, nb, link_m, groupable):
    """Places: intersections (>= 3 neighbours) joined by a street (through vertices with 2
    neighbours) whose ends lie at most link_m apart (the same rule for the net's junctions and
    the graph's nodes); vertex -> place."""
    parent = {j: j for j in pos}

    def find(a):
        while parent[a] != a:
            parent[a] = parent[parent[a]]
            a = parent[a]
        return a

    def joins(v):
        return groupable(v) and len(nb[v]) >= 3
    for v in sorted(pos, key=str):
        for w in sorted(nb[v], key=str) if joins(v) else ():
            end = chain_end(nb, v, w)
            if end != v and joins(end) and math.dist(pos[v], pos[end]) <= link_m:
                ru, rv = find(v), find(end)
                parent[max(ru, rv, key=str)] = min(ru, rv, key=str)
    return {j: find(j) for j in pos}


def place_truth(net_path, link_m):
    net = sumolib.net.readNet(net_path, withInternal=False)
    nb, pos, links = defaultdict(set), {}, []
    for e in net.getEdges():
        if not e.allows("passenger"):
            continue
        u, v = e.getFromNode().getID(), e.getToNode().getID()
        pos[u], pos[v] = e.getFromNode().getCoord()[:2], e.getToNode().getCoord()[:2]
        if u != v:
            nb[u].add(v)
            nb[v].add(u)
            links.append((u, v, e.getLength(), [p[:2] for p in e.getShape()]))
    place = group(pos, nb, link_m, lambda j: True)
    members, pnb, shapes = defaultdict(list), defaultdict(set), defaultdict(list)
    for j in sorted(pos):
        members[place[j]].append(j)
    for u, v, length, shape in links:
        a, b = place[u], place[v]
        if a != b:
            pnb[a].add(b)
            pnb[b].add(a)
            shapes[frozenset((a, b))].append((length, shape))
    return members, pnb, shapes, pos


def graph_places(g, nodes, end_nodes, link_m):
    """The graph's nodes grouped by the truth's rule (dead ends stay alone): node -> place."""
    nb = defaultdict(set)
    for e in g["edges"]:
        if e["u"] != e["v"]:
            nb[e["u"]].add(e["v"])
            nb[e["v"]].add(e["u"])
    return group(nodes, nb, link_m, lambda n: n not in end_nodes)


def chains_of(pnb, truth):
    chains = {}
    for v in truth:
        for w in pnb[v]:
            path = [v, w]
            while len(pnb[path[-1]]) == 2 and len(path) <= len(pnb):
                a, b = sorted(pnb[path[-1]])
                path.append(b if a == path[-2] else a)
            if len(pnb[path[-1]]) >= 3 and path[-1] != v:
                key = tuple(sorted((v, path[-1])))
                chains.setdefault(key, path if path[0] == key[0] else path[::-1])
    return chains


def match_nodes(nodes, det, dplace, truth, members, pos, radius):
    """Detected places to true places, closest pairs first; returns node -> true place (every
    node of a matched place) and true place -> the lowest node of its matched place."""
    dmembers = defaultdict(list)
    for d in det:
        dmembers[dplace[d]].append(d)
    pairs = sorted((min(math.dist(nodes[d], pos[j]) for d in dmembers[p] for j in members[t]), p, t)
                   for p in dmembers for t in truth)
    d2t, t2d = {}, {}
    for dist, p, t in pairs:
        if dist <= radius and dmembers[p][0] not in d2t and t not in t2d:
            for d in dmembers[p]:
                d2t[d] = t
            t2d[t] = min(dmembers[p])
    return d2t, t2d


def why(chain, path, ctx):
    a, b = chain
    if a not in ctx["t2d"] or b not in ctx["t2d"]:
        lost = [t for t in chain if t not in ctx["t2d"]]
        near = [d for d in ctx["det"] if d not in ctx["d2t"] and any(
            math.dist(ctx["nodes"][d], ctx["pos"][j]) <= 2 * ctx["radius"]
            for t in lost for j in ctx["members"][t])]
        return "end node not detected" + (" (tolerance: node %s)" % near if near else "")
    lane_pts = [p for x, y in zip(path, path[1:]) for _, s in ctx["shapes"][frozenset((x, y))]
                for p in samples(s)]
    grid = Grid(lane_pts)
    along = [s for s, pl in ctx["streets"].items()
             if sum(grid.near(p, ALONG_M) for p in pl) >= ALONG_SHARE * len(pl)]
    if not along:
        return "no street"
    ends = {n for s in along for n in ctx["ends_of"][s] if ctx["d2t"].get(n) not in (a, b)}
    others = sorted(n for n in ends if n in ctx["d2t"])
    if others:
        return "geometry mismatch (street %s ends at node %s)" % (along, others)
    return "edge split (streets %s meet at %s)" % (along, ", ".join(describe(n, ctx) for n in ends))


def describe(n, ctx):
    """A node that is no true place: dead end or false node, and the junction nearest to it."""
    j = min(ctx["pos"], key=lambda j: math.dist(ctx["pos"][j], ctx["nodes"][n]))
    kind = "dead end" if n in ctx["end_nodes"] else "false node"
    other = ctx["t2d"].get(ctx["place"][j])
    return "%s %d, %.0f m from %s (%d neighbouring places%s)" % (
        kind, n, math.dist(ctx["pos"][j], ctx["nodes"][n]), j, len(ctx["pnb"][ctx["place"][j]]),
        ", its place matched by node %d" % other if other is not None else "")


def trace_cells(path):
    cells = set()
    with open(path) as f:
        head = f.readline().strip().split(",")
        ix, iy = head.index("x"), head.index("y")
        for line in f:
            row = line.split(",")
            cells.add((int(float(row[ix]) // DRIVEN_M), int(float(row[iy]) // DRIVEN_M)))
    return cells


def driven_arms(place, ctx):
    """How many of a place's arms the traces run along (DRIVEN_SKIP_M to 2 x that from it, on
    either carriageway; an arm shorter than that is followed through places with 2 neighbours)."""
    own = [ctx["pos"][j] for j in ctx["members"][place]]
    count = 0
    for other in ctx["pnb"][place]:
        prev, cur, pts = place, other, []
        for _ in range(10):
            pts += [p for _, s in ctx["shapes"][frozenset((prev, cur))] for p in samples(s)
                    if DRIVEN_SKIP_M < min(math.dist(p, q) for q in own) <= 2 * DRIVEN_SKIP_M]
            if len(ctx["pnb"][cur]) != 2 or min(
                    math.dist(ctx["pos"][j], q) for j in ctx["members"][cur] for q in own) > \
                    2 * DRIVEN_SKIP_M:
                break
            prev, cur = cur, next(n for n in ctx["pnb"][cur] if n != prev)
        count += bool(pts) and driven_share(pts, ctx["trace_cells"]) >= ARM_SHARE
    return count


def driven_share(pts, cells):
    hit = sum(any((int(p[0] // DRIVEN_M) + i, int(p[1] // DRIVEN_M) + j) in cells
                  for i in (-1, 0, 1) for j in (-1, 0, 1)) for p in pts)
    return hit / len(pts)


def driven(path, ctx):
    """Whether the survey's traces run along most of the chain's lanes (away from its ends)."""
    ends = [ctx["pos"][j] for t in (path[0], path[-1]) for j in ctx["members"][t]]
    pts = [p for x, y in zip(path, path[1:]) for _, s in ctx["shapes"][frozenset((x, y))]
           for p in samples(s) if min(math.dist(p, q) for q in ends) > DRIVEN_SKIP_M]
    if not pts:
        return True
    return (driven_share(pts, ctx["trace_cells"]) >= DRIVEN_SHARE and
            all(driven_arms(t, ctx) >= 3 for t in (path[0], path[-1])))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("net")
    ap.add_argument("graph")
    ap.add_argument("--link", type=float, default=38.0)
    ap.add_argument("--radius", type=float, default=15.0)
    ap.add_argument("--traces", help="the survey's traces.csv: mark each chain driven or not")
    args = ap.parse_args()
    members, pnb, shapes, pos = place_truth(args.net, args.link)
    truth = sorted(t for t in pnb if len(pnb[t]) >= 3)
    chains = chains_of(pnb, truth)
    g = json.load(open(args.graph))
    meta = g["metadata"] if isinstance(g["metadata"], dict) else json.loads(g["metadata"])
    end_nodes = set(meta["end_nodes"])
    nodes = {n["id"]: (n["x"], n["y"]) for n in g["nodes"]}
    det = sorted(n for n in nodes if n not in end_nodes)
    d2t, t2d = match_nodes(nodes, det, graph_places(g, nodes, end_nodes, args.link), truth,
                           members, pos, args.radius)
    streets, ends_of, found = {}, {}, set()
    for e in g["edges"]:
        s = e.get("street", e["id"])
        if s in streets:
            continue
        streets[s] = samples([tuple(p[:2]) for p in e["polyline"]])
        ends_of[s] = (e["u"], e["v"])
        if e["u"] in d2t and e["v"] in d2t:
            key = tuple(sorted((d2t[e["u"]], d2t[e["v"]])))
            if key in chains:
                found.add(key)
    ctx = dict(t2d=t2d, d2t=d2t, det=det, nodes=nodes, pos=pos, members=members, radius=args.radius,
               shapes=shapes, streets=streets, ends_of=ends_of, end_nodes=end_nodes, pnb=pnb,
               place={j: t for t, js in members.items() for j in js},
               trace_cells=trace_cells(args.traces) if args.traces else None)
    print("places %d, true chains %d, found %d (recall %.3f); graph.json: %d / %d (%.3f)" % (
        len(truth), len(chains), len(found), len(found) / max(1, len(chains)),
        meta["place_validation"]["found_chains"], meta["place_validation"]["true_chains"],
        meta["place_validation"]["edge_recall"]))
    if args.traces:
        was_driven = {k for k in chains if driven(chains[k], ctx)}
        print("driven chains %d of %d; found %d of them (recall over driven chains %.3f)" % (
            len(was_driven), len(chains), len(found & was_driven),
            len(found & was_driven) / max(1, len(was_driven))))
    for key in sorted(chains):
        if key in found:
            continue
        path = chains[key]
        length = sum(min(x for x, _ in shapes[frozenset((a, b))]) for a, b in zip(path, path[1:]))
        xy = [tuple(round(c) for c in pos[members[t][0]]) for t in key]
        print("%-28s %-28s nodes %4s %4s  %6.0f m  at %s %s  %s" % (
            key[0][:28], key[1][:28], t2d.get(key[0], "-"), t2d.get(key[1], "-"), length,
            xy[0], xy[1], why(key, path, ctx)) +
              ("" if not args.traces else "  [driven]" if key in was_driven else "  [not driven]"))


if __name__ == "__main__":
    main()
