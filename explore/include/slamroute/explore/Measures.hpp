#pragma once
// Measures of an exploration (Explore.hpp): milestones on the coverage curve and the offline
// bound it is compared with.
#include <cstdint>
#include <vector>

#include "slamroute/core/RoadGraph.hpp"
#include "slamroute/explore/Explore.hpp"
#include "slamroute/rl/PlanGraph.hpp"

namespace slamroute::explore {

/// First point of the curve where edges_driven >= share * total_edges (share in (0, 1]);
/// reached = false when the curve never gets there.
Milestone milestoneAt(const std::vector<CoverageSample>& curve, int total_edges, double share);

/// The offline fleet plan that knows the map (rl planFleet, `partition`): K closed legal routes,
/// one from each vehicle's start node, that together drive every directed street.
struct OfflineBound {
  double total_m = 0.0;     ///< summed route length: what an exploring fleet's distance is over
  double makespan_m = 0.0;  ///< the longest route [m]
};
/// start_edges: the explorers' first PlanGraph edges (one per vehicle); each route leaves the
/// node the edge starts at.
OfflineBound offlineFleetBound(const RoadGraph& g, const rl::PlanGraph& pg,
                               const std::vector<int>& start_edges, std::uint64_t seed);

}  // namespace slamroute::explore
