#pragma once
// The graph every planner works on: a compact copy of a RoadGraph restricted to its largest
// part that can be driven legally end to end (strongly connected under the turn permissions),
// stored as flat arrays (CSR) so the Q-learning inner loop allocates nothing.
//
// Turn permissions: a position is an *edge state* ("just drove edge e, now at v(e)"); the actions
// from it are the edges allowed after e (RoadGraph::nextEdges: SUMO <connection>s, so forbidden
// turns and U-turns are never offered). At the very start there is no arrival edge: the *node
// state* of the start node offers every edge leaving it.
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "slamroute/core/RoadGraph.hpp"

namespace slamroute::rl {

struct PlanGraph {
  int n = 0, m = 0;               ///< nodes, edges (local ids 0..n-1, 0..m-1)
  std::vector<int> node_orig;     ///< local node -> RoadGraph node id
  std::vector<int> edge_orig;     ///< local edge -> RoadGraph edge id
  std::vector<int> node_local;    ///< RoadGraph node id -> local id, -1 when dropped
  std::vector<int> u, v, street;  ///< per edge; street ids are compact 0..num_streets-1
  std::vector<double> len;        ///< per edge [m]
  std::vector<double> weight;     ///< per edge, normalised to [0, 1] (weight / max weight)
  std::vector<double> heading;    ///< per edge, chord heading from u to v [rad]
  std::vector<int> next_off,
      next;  ///< CSR: edges allowed after edge e: next[next_off[e]..next_off[e+1])
  std::vector<int> out_off, out;  ///< CSR: edges leaving node i
  int num_streets = 0;
  std::vector<double> street_len;            ///< per street: length of its longest direction [m]
  double total_street_len = 0.0;             ///< [m]
  double total_edge_len = 0.0;               ///< sum of directed edge lengths [m]
  double mean_len = 1.0;                     ///< mean edge length [m]
  bool restricted = false;                   ///< turn permissions apply
  int dropped_nodes = 0, dropped_edges = 0;  ///< outside the largest legally connected part

  /// Largest strongly connected part under the turn permissions (components of the line graph,
  /// the biggest by edge count). Throws std::invalid_argument naming `where` when the graph has
  /// no edge or no drivable cycle.
  static PlanGraph build(const RoadGraph& g, const std::string& where = "graph");

  int nextBegin(int e) const { return next_off[static_cast<std::size_t>(e)]; }
  int nextEnd(int e) const { return next_off[static_cast<std::size_t>(e) + 1]; }
  int outBegin(int i) const { return out_off[static_cast<std::size_t>(i)]; }
  int outEnd(int i) const { return out_off[static_cast<std::size_t>(i) + 1]; }
};

/// Shortest legal paths on the turn-expanded (line) graph with Boost's Dijkstra.
/// Vertex e < m is the edge state of edge e, vertex m + i the node state of node i.
class TurnPaths {
 public:
  explicit TurnPaths(const PlanGraph& pg);

  struct Path {
    std::vector<int> edges;  ///< edges driven after the source state, in order
    double length_m = 0.0;
  };
  /// Shortest path from the edge state `from_edge` (or, when from_edge < 0, the node state of
  /// `from_node`) to the nearest edge e with goal(e) true (the path ends by driving e).
  std::optional<Path> toNearest(int from_edge, int from_node,
                                const std::function<bool(int)>& goal) const;
  /// Distance from the source state to every edge state (driving it last); +inf if unreachable.
  std::vector<double> distances(int from_edge, int from_node) const;
  /// Distances and predecessors (edge-state vertices) from the source state.
  void run(int from_edge, int from_node, std::vector<double>& dist, std::vector<int>& pred) const;

 private:
  struct Impl;
  const PlanGraph& pg_;
  std::shared_ptr<Impl> impl_;
};

}  // namespace slamroute::rl
