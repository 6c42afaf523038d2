#!/usr/bin/env python3
"""Largest strongly connected part of a graph.json under its travel directions (which nodes a
planner can route between). Usage: bench/graph_connectivity.py GRAPH.json
"""
import collections
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from script_help import exit_on_help  # noqa: E402

exit_on_help(__doc__)
if len(sys.argv) != 2:
    sys.exit("usage: bench/graph_connectivity.py GRAPH.json")


def reach(s,adj):
    seen={s};st=[s]
    while st:
        u=st.pop()
        for v in adj[u]:
            if v not in seen: seen.add(v);st.append(v)
    return seen
g=json.load(open(sys.argv[1]))
adj=collections.defaultdict(set);radj=collections.defaultdict(set)
for e in g['edges']: adj[e['u']].add(e['v']); radj[e['v']].add(e['u'])
N=range(len(g['nodes']))
best=max((reach(n,adj)&reach(n,radj) for n in N),key=len)
print('graph nodes',len(g['nodes']),'edges',len(g['edges']),'SCC',len(best), sorted(set(N)-best))
print(g['metadata']['stats'])
