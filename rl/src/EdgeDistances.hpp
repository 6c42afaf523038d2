#pragma once
// Private helper of the coverage planners: shortest legal distances and paths between every pair
// of edge states of a PlanGraph (the turn-expanded graph), plus the rows from the start node.
// Memory: two (m + 1) x m matrices of 4 bytes; the callers cap m (rl.coverage.aco.max_edges).
#include <vector>

#include "slamroute/rl/PlanGraph.hpp"

namespace slamroute::rl::detail {

class EdgeDistances {
 public:
  /// One Dijkstra per edge state and one from the node state of `start`.
  EdgeDistances(const PlanGraph& pg, const TurnPaths& paths, int start);
  /// Legal distance from having driven `from` (-1: standing at the start node) to having driven
  /// `to` [m]; +inf when unreachable, 0 when from == to.
  float d(int from, int to) const { return dist_[row(from) + static_cast<std::size_t>(to)]; }
  /// Appends the edges of the shortest legal path from `from` to `to` (ending with `to`).
  void appendPath(int from, int to, std::vector<int>& out) const;
  /// Cheapest way from `from` back to the start node: the edge arriving there, -1 when `from`
  /// already ends at the start node.
  int returnEdge(int from) const;
  int edges() const { return m_; }

 private:
  std::size_t row(int from) const {
    return static_cast<std::size_t>(from < 0 ? m_ : from) * static_cast<std::size_t>(m_);
  }
  const PlanGraph* pg_;
  int m_ = 0, start_ = 0;
  std::vector<float> dist_;
  std::vector<int> pred_;  ///< predecessor edge state; -1 at the source or when unreachable
  std::vector<int> into_start_;
};

}  // namespace slamroute::rl::detail
