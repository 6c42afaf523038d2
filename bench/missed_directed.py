#!/usr/bin/env python3
"""Why a planned route misses directed SUMO edges (bench/RESULTS.md, "aco-ga against postman in
`run`").

Usage: bench/missed_directed.py NET.net.xml GRAPH.json ROUTE.json [ROUTE.json ...]

The directed coverage of route.json counts the passenger edges of the net's largest strongly
connected part over junctions (core/SumoCoverage.cpp), which ignores turn permissions. Each
edge of that part no route drives is put in the first class that fits:
  no legal route      not in the largest strongly connected part of the edge-to-edge graph under
                      SUMO's passenger connections: no legal drive enters it and comes back
                      (e.g. a two-way street to the map border where a car cannot turn round)
  no graph edge       no edge of the graph has it in its SUMO chain (the builder lost it)
  dropped by planner  a graph edge has it, but that edge is outside the graph's largest part
                      strongly connected under its turns, which the planners keep
  not driven          in the planning graph, yet no route drives it
Prints the counts, then one line per edge. Needs sumolib (Debian sumo-tools: $SUMO_HOME/tools).
"""
import json
import os
import sys
from collections import defaultdict

sys.path.insert(0, os.path.join(os.environ.get("SUMO_HOME", "/usr/share/sumo"), "tools"))
import sumolib  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "networks"))
sys.dont_write_bytecode = True  # keep networks/ free of __pycache__
from check import largest_scc  # noqa: E402  (iterative Tarjan, shared with the net checks)

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from script_help import exit_on_help  # noqa: E402


def net_parts(path):
    """Passenger edges of the junction-level largest SCC, and of the turn-level one."""
    net = sumolib.net.readNet(path, withInternal=False)
    edges = [e for e in net.getEdges() if e.allows("passenger")]
    jsucc = defaultdict(set)
    for e in edges:
        jsucc[e.getFromNode().getID()].add(e.getToNode().getID())
    jscc = set(largest_scc(sorted(jsucc), jsucc))
    in_j = {e.getID() for e in edges
            if e.getFromNode().getID() in jscc and e.getToNode().getID() in jscc}
    esucc = defaultdict(set)
    for e in edges:
        for to, conns in e.getOutgoing().items():
            if to.allows("passenger") and any(
                    c.getFromLane().allows("passenger") and c.getToLane().allows("passenger")
                    for c in conns):
                esucc[e.getID()].add(to.getID())
    in_t = set(largest_scc(sorted(e.getID() for e in edges), esucc))
    return in_j, in_t, {e.getID(): e.getLength() for e in edges}


def planning_edges(g):
    """Graph edge ids in the largest part strongly connected under the graph's turns."""
    succ = defaultdict(set)
    for i, after in enumerate(g["turns"]):
        succ[i].update(after)
    return set(largest_scc(range(len(g["edges"])), succ))


def main():
    exit_on_help(__doc__)
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    in_j, in_t, length = net_parts(sys.argv[1])
    g = json.load(open(sys.argv[2]))
    driven = set()
    for path in sys.argv[3:]:
        driven.update(json.load(open(path))["sumo_edges"])
    kept = planning_edges(g)
    graph_edges = defaultdict(list)
    for e in g["edges"]:
        for s in e.get("sumo_edges", []):
            graph_edges[s].append(e["id"])
    rows, counts = [], defaultdict(int)
    for s in sorted(in_j - driven):
        if s not in in_t:
            why = "no legal route"
        elif not graph_edges[s]:
            why = "no graph edge"
        elif not any(i in kept for i in graph_edges[s]):
            why = "dropped by planner"
        else:
            why = "not driven"
        counts[why] += 1
        rows.append("%-14s %7.1f m  %-18s graph edges %s" % (s, length[s], why, graph_edges[s]))
    legal = len(in_j & in_t)
    print("junction-level part %d edges, of them legally drivable %d; driven %d (%.1f %%), "
          "of the legal part %d (%.1f %%)" % (
              len(in_j), legal, len(in_j & driven), 100.0 * len(in_j & driven) / len(in_j),
              len(in_j & in_t & driven), 100.0 * len(in_j & in_t & driven) / max(1, legal)))
    print("missed: " + ", ".join("%s %d" % kv for kv in sorted(counts.items())))
    for r in rows:
        print(r)


if __name__ == "__main__":
    main()
