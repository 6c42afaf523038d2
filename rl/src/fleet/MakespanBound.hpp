#pragma once
// Private to the fleet planner: a lower bound on the makespan that counts every vehicle's drive
// out from its depot and back (MakespanBound.cpp derives it), and one that also counts the
// detours between far streets (FlowBound.cpp).
#include <vector>

#include "FleetParts.hpp"

namespace slamroute::rl::fleet {

/// One directed edge as the bound sees it.
struct EdgeReach {
  double len_m = 0.0;     ///< the edge's length
  double before_m = 0.0;  ///< shortest legal drive from a depot to where the edge may be taken
  double after_m = 0.0;   ///< shortest legal drive from the edge's end back to a depot
};

/// The distinct finite values, ascending, at most max_count (>= 2) of them evenly spaced in
/// sorted order (the smallest and the largest among them): the thresholds the bounds try.
std::vector<double> spreadThresholds(std::vector<double> values, int max_count);

/// Per edge of the planning graph: its length and its legal distances from and back to the
/// nearest depot (FleetContext's).
std::vector<EdgeReach> edgeReaches(const FleetContext& ctx);

/// max over thresholds (a, b) of a + b + L(F) / vehicles, F = the edges with before_m >= a and
/// after_m >= b, L(F) their summed length; no legal solution of `vehicles` closed walks from the
/// depots that drives every edge has a shorter makespan. At most max_thresholds values of a are
/// tried (evenly spaced in sorted order); fewer only weaken the bound, never invalidate it.
double depotTripsBound(const std::vector<EdgeReach>& edges, int vehicles,
                       int max_thresholds = 1000);

/// max over far sets F of min over r in 1..vehicles of C_F(r) / r, C_F(r) the cheapest
/// circulation on the turn-expanded graph in which r walks, each from a depot's reach of an F
/// edge to a depot's reach after one, drive every edge of F (FlowBound.cpp derives it). F: the
/// edges whose round trip before + len + after is at least a threshold, at most max_sets
/// thresholds. No legal solution has a shorter makespan.
double farFlowBound(const PlanGraph& pg, const std::vector<EdgeReach>& reach, int vehicles,
                    int max_sets = 24);

}  // namespace slamroute::rl::fleet
