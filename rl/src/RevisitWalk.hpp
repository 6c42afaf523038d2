#pragma once
// Private helper of the coverage planners: drives a coverage tour (the ACO city order) and
// inserts loop-closure revisits chosen by a policy, tracking C_k (Uncertainty.hpp) as it goes.
//
// The walk takes the cities in order, skips those already driven, and reaches each by its
// shortest legal path (a "coverage leg"). After leg j (city index j) and while streets are still
// uncovered, the policy may name a revisit: an edge f arriving at a loop-closure place, driven to
// by the shortest legal path; the next leg then starts from f. Every directed street is driven
// whatever the policy says, and every step is a legal turn.
#include <functional>
#include <vector>

#include "EdgeDistances.hpp"
#include "slamroute/rl/Uncertainty.hpp"

namespace slamroute::rl::detail {

struct CoverageProblem {
  const PlanGraph& pg;
  const EdgeDistances& dist;
  const std::vector<int>& cities;
  int start = 0;
  bool closed = true;
  const EifConfig& eif;
  EdgeMotions motions;
  double c_threshold_m2 = 0.0;
  double place_max_c_m2 = 0.0;  ///< loop-closure places: stored C_k at most this [m^2]
};

struct WalkResult {
  std::vector<int> edges;
  std::vector<double> c_m2;        ///< C_k after each edge
  std::vector<int> reached;        ///< city indices reached by a coverage leg, in order
  std::vector<int> revisit_after;  ///< city indices after which a revisit was driven
  double length_m = 0.0, revisit_length_m = 0.0;
  double max_c_m2 = 0.0, excess_m2 = 0.0;  ///< excess: sum over steps of max(0, C_k - bound)
  bool feasible() const { return excess_m2 <= 0.0; }
};

/// Where the walk stands after a coverage leg: city index j, `cur` the edge just driven,
/// `after` the edge the walk heads for next (the next uncovered city, or the edge back to the
/// start when none is left; -1 when nothing follows), `last` when no city is left.
struct WalkState {
  int j = 0, cur = -1, after = -1;
  bool last = false;
};
/// The revisit to insert at that point: an edge into a loop-closure place, or -1.
using RevisitPolicy = std::function<int(const WalkState& s, const UncertaintyTracker& t)>;

WalkResult walkCoverage(const CoverageProblem& p, const RevisitPolicy& policy);

/// Nearest loop-closure revisit from `cur` before heading to `after` (-1: nowhere): the edge f
/// into a mapped node w != v(cur) with stored C_k <= place_max_c_m2 and below the current C_k, and
/// a loop (at least eif.loop_min_travel_m driven since the last visit of w on arrival), minimising
/// d(cur, f) + d(f, after). -1 when there is none.
int nearestRevisit(const CoverageProblem& p, const UncertaintyTracker& t, int cur, int after);

/// Switching (paper's SW): revisit now when going on to the next city and revisiting only
/// there would exceed the bound. Records the revisit it considered after every city index in
/// `considered` (the GA's gene targets).
WalkResult walkSwitching(const CoverageProblem& p, std::vector<int>& considered);

}  // namespace slamroute::rl::detail
