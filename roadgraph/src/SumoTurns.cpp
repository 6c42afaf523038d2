// Turn permissions of a trace-built graph from the SUMO net it was matched to: the graph knows
// which streets meet at a node, but not which turns the road allows (no U-turn on a divided
// road, no left turn across a median, no way back out of a street that leaves the map). A turn
// e -> f at a node is allowed when SUMO leads from e's last SUMO edge to f's first one over at
// most `turn_max_detour_m` of edges in between (junction complexes of divided roads need a
// short edge or two; going round a block is longer), plus the stretch of road between the node
// and the ends of the two chains, which the lane matching leaves out near nodes. Edges without
// SUMO edges (short links SUMO models inside a junction) keep every turn except straight back
// onto their own street.
#include <algorithm>
#include <functional>
#include <queue>

#include "slamroute/core/DriveGraph.hpp"
#include "slamroute/roadgraph/SumoMatch.hpp"

namespace slamroute::roadgraph {
namespace {

/// The net's passenger edges and allowed turns (core DriveGraph) with a bounded search on them.
struct SumoLineGraph {
  DriveGraph dg;

  explicit SumoLineGraph(const SumoNet& net) : dg(DriveGraph::fromNet(net)) {}

  /// Per edge, the least length of the edges driven in between to reach it from `from`
  /// (entering an edge is free; driving through it costs its length); -1 when that exceeds
  /// `cap` or the edge cannot be reached.
  std::vector<double> inBetween(std::size_t from, double cap) const {
    std::vector<double> dist(dg.numEdges(), -1.0), reach(dg.numEdges(), -1.0);
    using Item = std::pair<double, std::size_t>;
    std::priority_queue<Item, std::vector<Item>, std::greater<>> q;
    q.push({0.0, from});
    dist[from] = 0.0;
    while (!q.empty()) {
      const auto [d, x] = q.top();
      q.pop();
      if (d > dist[x]) continue;
      for (std::size_t y : dg.allowed_next[x]) {
        if (reach[y] < 0.0 || d < reach[y]) reach[y] = d;
        const double dy = d + dg.edges[y].length_m;
        if (y != from && dy <= cap && (dist[y] < 0.0 || dy < dist[y])) {
          dist[y] = dy;
          q.push({dy, y});
        }
      }
    }
    return reach;
  }
};

constexpr double kMaxGapOut = 300.0;  ///< cap on the node-to-chain stretch counted [m]

double distance2d(const Point3& a, const Point3& b) { return (a - b).head<2>().norm(); }

/// Where a SUMO edge starts / ends: the first / last point of its shape.
Point3 junctionStart(const SumoNet& net, const std::string& id) {
  const SumoEdge* e = net.findEdge(id);
  return e && !e->shape.empty() ? e->shape.front() : Point3::Zero();
}
Point3 junctionEnd(const SumoNet& net, const std::string& id) {
  const SumoEdge* e = net.findEdge(id);
  return e && !e->shape.empty() ? e->shape.back() : Point3::Zero();
}

}  // namespace

TurnStats turnsFromNet(RoadGraph& graph, const SumoNet& net, const SumoMatchConfig& cfg) {
  const SumoLineGraph lg(net);
  auto sumoIndex = [&](const std::string& id) -> long {
    const auto it = lg.dg.edge_of.find(id);
    return it == lg.dg.edge_of.end() ? -1 : static_cast<long>(it->second);
  };
  const auto out = graph.outEdges();
  TurnStats st;
  graph.allowed_next.assign(graph.edges.size(), {});
  for (const auto& e : graph.edges) {
    const Point3& node = graph.nodes[static_cast<std::size_t>(e.v)].pos;
    const long last = e.sumo_edges.empty() ? -1 : sumoIndex(e.sumo_edges.back());
    double gap_in = 0.0;  // from the end of e's last SUMO edge to the node [m]
    std::vector<double> reach;
    if (last >= 0) {
      gap_in = distance2d(junctionEnd(net, e.sumo_edges.back()), node);
      reach =
          lg.inBetween(static_cast<std::size_t>(last), cfg.turn_max_detour_m + gap_in + kMaxGapOut);
    }
    for (int fid : out[static_cast<std::size_t>(e.v)]) {
      const auto& f = graph.edges[static_cast<std::size_t>(fid)];
      ++st.candidate_turns;
      const long first = f.sumo_edges.empty() ? -1 : sumoIndex(f.sumo_edges.front());
      bool ok;
      if (last < 0 || first < 0) {
        ok = !(f.street == e.street && f.street >= 0 && f.v == e.u);  // not straight back
      } else if (last == first) {
        ok = true;  // the same SUMO edge runs on through the node
      } else {
        const double gap_out =
            std::min(kMaxGapOut, distance2d(junctionStart(net, f.sumo_edges.front()), node));
        const double d = reach[static_cast<std::size_t>(first)];
        ok = d >= 0.0 && d <= cfg.turn_max_detour_m + gap_in + gap_out;
      }
      if (ok)
        graph.allowed_next[static_cast<std::size_t>(e.id)].push_back(fid);
      else
        ++st.forbidden_turns;
    }
  }
  graph.restricted_turns = true;
  return st;
}

}  // namespace slamroute::roadgraph
