#pragma once
// Private helper of the planners: coverage bookkeeping for the goal (every node visited or every
// street driven) and completion of a route by shortest legal paths to the nearest uncovered part.
#include <vector>

#include "slamroute/rl/Planners.hpp"

namespace slamroute::rl::detail {

class Coverage {
 public:
  Coverage(const PlanGraph& pg, Goal goal, int start) : pg_(pg), goal_(goal) {
    node_.assign(static_cast<std::size_t>(pg.n), 0);
    street_.assign(static_cast<std::size_t>(pg.num_streets), 0);
    remaining_ = goal == Goal::Nodes ? pg.n : pg.num_streets;
    if (goal == Goal::Nodes) {
      node_[static_cast<std::size_t>(start)] = 1;
      --remaining_;
    }
  }
  /// Driving edge e covers something new.
  bool isNew(int e) const {
    return goal_ == Goal::Nodes
               ? !node_[static_cast<std::size_t>(pg_.v[static_cast<std::size_t>(e)])]
               : !street_[static_cast<std::size_t>(pg_.street[static_cast<std::size_t>(e)])];
  }
  /// Records driving e; returns whether it covered something new.
  bool drive(int e) {
    if (!isNew(e)) return false;
    if (goal_ == Goal::Nodes)
      node_[static_cast<std::size_t>(pg_.v[static_cast<std::size_t>(e)])] = 1;
    else
      street_[static_cast<std::size_t>(pg_.street[static_cast<std::size_t>(e)])] = 1;
    --remaining_;
    return true;
  }
  bool done() const { return remaining_ == 0; }
  int remaining() const { return remaining_; }

 private:
  const PlanGraph& pg_;
  Goal goal_;
  std::vector<char> node_, street_;
  int remaining_ = 0;
};

/// Appends shortest legal paths to the nearest uncovered part until the goal is met.
/// Returns the number of path segments and adds their length to *length_m.
inline int completeByShortestPaths(const PlanGraph& pg, const TurnPaths& paths, Coverage& cov,
                                   int start, std::vector<int>& edges, double* length_m) {
  int segments = 0;
  while (!cov.done()) {
    const int cur_edge = edges.empty() ? -1 : edges.back();
    auto p = paths.toNearest(cur_edge, start, [&cov](int e) { return cov.isNew(e); });
    if (!p) break;  // cannot happen on a strongly connected PlanGraph
    for (int e : p->edges) {
      cov.drive(e);
      edges.push_back(e);
    }
    *length_m += p->length_m;
    ++segments;
  }
  (void)pg;
  return segments;
}

}  // namespace slamroute::rl::detail
