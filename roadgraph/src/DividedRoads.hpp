#pragma once
// Internal to roadgraph: divided roads as one street with two directions (DividedRoads.cpp).
#include "slamroute/roadgraph/Config.hpp"
#include "slamroute/roadgraph/GraphBuilder.hpp"

namespace slamroute::roadgraph::detail {

/// Merges the nodes on the two carriageways of a divided road into one node per place, drops the
/// streets inside a merged place and gives the two carriageways between two places one street
/// id. Updates out.graph, out.node_is_end and the node / street counts in out.stats.
void mergeDividedRoads(GraphBuildResult& out, const DividedRoadConfig& cfg, double half_height_m);

}  // namespace slamroute::roadgraph::detail
