#pragma once
// Shortest legal paths over the part of the net the fleet knows: Dijkstra on the turn-expanded
// graph (a state is "just drove edge e"), moving only onto known edges through SUMO's turns.
// Multi-goal searches ("the nearest uncovered street") are Dijkstra, i.e. A* with a zero
// heuristic: with many goals no single straight-line bound applies.
#include <functional>
#include <optional>
#include <vector>

#include "slamroute/rl/PlanGraph.hpp"

namespace slamroute::explore {

struct KnownPath {
  std::vector<int> edges;  ///< edges driven after the current one, the last is the goal
  double length_m = 0.0;
};

class KnownPaths {
 public:
  /// Distances from the state "on edge `from`" (its own length not counted) over edges for
  /// which known(e) holds; dist[e] includes driving e; +inf when unreachable.
  KnownPaths(const rl::PlanGraph& pg, int from, const std::function<bool(int)>& known);
  double distance(int edge) const { return dist_[static_cast<std::size_t>(edge)]; }
  /// The path to `edge`, nullopt when unreachable (or edge == from).
  std::optional<KnownPath> pathTo(int edge) const;
  /// The reachable edge with goal(e) true nearest to the start (ties: lowest id).
  std::optional<int> nearest(const std::function<bool(int)>& goal) const;

 private:
  const rl::PlanGraph& pg_;
  int from_;
  std::vector<double> dist_;
  std::vector<int> pred_;
};

}  // namespace slamroute::explore
