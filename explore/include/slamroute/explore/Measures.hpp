#pragma once
// Measures of an exploration (Explore.hpp): milestones on the coverage curve and the offline
// bound it is compared with.
#include <vector>

#include "slamroute/explore/Explore.hpp"
#include "slamroute/rl/PlanGraph.hpp"

namespace slamroute::explore {

/// First point of the curve where edges_driven >= share * total_edges (share in (0, 1]);
/// reached = false when the curve never gets there.
Milestone milestoneAt(const std::vector<CoverageSample>& curve, int total_edges, double share);

/// The offline plan that knows the map: the legal postman walk over every directed street from
/// the start edge's node (rl planPostman) [m]. A fleet's summed distance is compared with it.
double offlineBoundLength(const rl::PlanGraph& pg, int start_edge);

}  // namespace slamroute::explore
