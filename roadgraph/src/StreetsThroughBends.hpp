#pragma once
// Internal to roadgraph: the graph as the validation against a SUMO net scores it
// (StreetsThroughBends.cpp).
#include <vector>

#include "slamroute/core/RoadGraph.hpp"

namespace slamroute::roadgraph::detail {

/// The streets of `graph` joined through its nodes that are not intersections (`node_kind`,
/// GraphBuildResult::node_is_end) and end exactly two streets: a turning place, a corner where
/// two dead ends met. The truth's chains run through the net's junctions with two neighbours in
/// the same way. One edge per joined street, without polyline; the nodes are the graph's (the
/// ones passed through keep no edge), so node ids, and the SUMO junction the validation matches
/// to each, stay the graph's.
RoadGraph streetsThroughBends(const RoadGraph& graph, const std::vector<char>& node_kind);

}  // namespace slamroute::roadgraph::detail
