#!/usr/bin/env python3
"""Checks on build-graph's node validation (bench/RESULTS.md, "Road graph: node and edge accuracy").

Usage: bench/node_f1_checks.py NET.net.xml GRAPH.json [GRAPH.json ...] [--diagnose]

For each graph.json written by `slamroute build-graph --net NET` it prints:
- the node F1 of build-graph's greedy closest-first matching and of a maximum-cardinality
  one-to-one matching within the same 15 m (augmenting paths): does the matching cost matches?
- the loop rule: F1 if nodes with >= 3 streets but < 3 distinct neighbouring nodes were not
  counted (the truth's ">= 3 distinct neighbours" applied to such nodes only). An estimate: a
  dropped matched node leaves its junction missed (no re-matching).
With --diagnose, each false node and missed junction with the SUMO junctions / nodes near it.
Standard library only. The truth set is read back from the graph (matched + missed junctions).
"""
import json
import math
import os
import sys
import xml.etree.ElementTree as ET
from collections import defaultdict

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from script_help import exit_on_help  # noqa: E402

MATCH_RADIUS_M = 15.0  # roadgraph.sumo.match_radius_m default


def junctions(net_path):
    pos = {}
    for e in ET.parse(net_path).getroot().iter("junction"):
        if e.get("type") != "internal":
            pos[e.get("id")] = (float(e.get("x")), float(e.get("y")))
    return pos


def f1(tp, detected, truth):
    return 2.0 * tp / (detected + truth) if detected + truth else 0.0


def max_matching(det, truth, pos):
    adj = {n["id"]: [t for t in truth if math.dist((n["x"], n["y"]), pos[t]) <= MATCH_RADIUS_M]
           for n in det}
    owner = {}

    def augment(u, seen):
        for t in adj[u]:
            if t not in seen:
                seen.add(t)
                if t not in owner or augment(owner[t], seen):
                    owner[t] = u
                    return True
        return False

    return sum(1 for n in det if augment(n["id"], set()))


def loop_nodes(graph):
    streets, nbr = defaultdict(set), defaultdict(set)
    for e in graph["edges"]:
        for a, b in ((e["u"], e["v"]), (e["v"], e["u"])):
            streets[a].add(e["street"])
            if b != a:
                nbr[a].add(b)
    return {n["id"] for n in graph["nodes"] if len(streets[n["id"]]) >= 3 and len(nbr[n["id"]]) < 3}


def diagnose(graph, val, pos):
    nodes = {n["id"]: n for n in graph["nodes"]}
    by_junction = {n["sumo_junction"]: n["id"] for n in graph["nodes"] if n.get("sumo_junction")}
    for f in val["false_nodes"]:
        n = nodes[f]
        near = sorted((math.dist((n["x"], n["y"]), p), j) for j, p in pos.items())[:3]
        desc = []
        for d, j in near:
            tag = "missed" if j in val["missed_junctions"] else (
                "matched by node %d" % by_junction[j] if j in by_junction else "not a truth junction")
            desc.append("%s %.1f m (%s)" % (j, d, tag))
        print("  false node %d (%.0f, %.0f): %s" % (f, n["x"], n["y"], "; ".join(desc)))
    for j in val["missed_junctions"]:
        near = sorted((math.dist((n["x"], n["y"]), pos[j]), n["id"]) for n in graph["nodes"])[:2]
        print("  missed %s (%.0f, %.0f): nearest nodes %s" % (
            j, *pos[j], ", ".join("%d %.1f m" % (i, d) for d, i in near)))


def main(argv):
    exit_on_help(__doc__)
    args = [a for a in argv if a != "--diagnose"]
    if len(args) < 2:
        sys.exit(__doc__)
    pos = junctions(args[0])
    for path in args[1:]:
        graph = json.load(open(path))
        val = graph["metadata"]["validation"]
        ends = set(graph["metadata"]["end_nodes"])
        det = [n for n in graph["nodes"] if n["id"] not in ends]
        truth = sorted({n["sumo_junction"] for n in det if n.get("sumo_junction")}
                       | set(val["missed_junctions"]))
        tp = val["matched_nodes"]
        best = max_matching(det, truth, pos)
        loops = loop_nodes(graph) - ends
        false = set(val["false_nodes"])
        lost = len(loops - false)
        print("%s: %d true, %d detected; F1 greedy %.3f (%d), maximum matching %.3f (%d); "
              "loop rule %.3f (%d false and %d matched nodes dropped)" % (
                  path, len(truth), len(det), f1(tp, len(det), len(truth)), tp,
                  f1(best, len(det), len(truth)), best,
                  f1(tp - lost, len(det) - len(loops), len(truth)), len(loops & false), lost))
        if "--diagnose" in argv:
            diagnose(graph, val, pos)


if __name__ == "__main__":
    main(sys.argv[1:])
