#pragma once
// Internal to roadgraph: divided roads as one street with two directions (DividedRoads.cpp), and
// staggered T junctions as one place (StaggeredJunctions.cpp).
#include <Eigen/Core>

#include "slamroute/core/UnionFind.hpp"
#include "slamroute/roadgraph/Config.hpp"
#include "slamroute/roadgraph/GraphBuilder.hpp"

namespace slamroute::roadgraph::detail {

/// Merges the nodes on the two carriageways of a divided road into one node per place, and the
/// two T junctions of a staggered pair into one, drops the streets inside a merged place and
/// gives the two carriageways between two places one street id. Updates out.graph,
/// out.node_is_end and the node / street counts in out.stats.
void mergeDividedRoads(GraphBuildResult& out, const DividedRoadConfig& cfg, double half_height_m);

/// The point `s` metres along pl from its start (from its end when from_end).
Eigen::Vector2d pointAlong(const Polyline& pl, double s, bool from_end);

/// Nodes that may join a place: intersections, not the junctions of a roundabout (whose one-way
/// ring arcs run side by side with the split arms joining it).
std::vector<char> mergeableNodes(const GraphBuildResult& out);

/// Staggered T junctions: pairs of mergeable nodes with three neighbours each, joined by an edge
/// and at most cfg.stagger_max_gap_m apart, where the street through both runs straight on
/// (within cfg.stagger_straight_deg) and the third arms leave on opposite sides of it. Each node
/// is in at most one pair (closest pairs first). Returns the sets (pairs counted in `pairs`);
/// `weight` is 0 for the node of a pair that gives up its position (the other keeps its own, so
/// the merged node stays on a junction).
slamroute::UnionFind staggeredPairs(const GraphBuildResult& out, const DividedRoadConfig& cfg,
                                    double half_height_m, std::size_t& pairs,
                                    std::vector<double>& weight);

}  // namespace slamroute::roadgraph::detail
