#pragma once
// Internal to roadgraph: the graph as the validation against a SUMO net scores it
// (StreetsThroughBends.cpp).
#include <vector>

#include "slamroute/core/RoadGraph.hpp"

namespace slamroute::roadgraph::detail {

/// The streets of `graph` joined through its turning places (`node_kind`,
/// GraphBuildResult::node_is_end) that end exactly two streets: the truth's chains run through
/// the net's junctions with two neighbours in the same way. A corner where two dead ends met
/// stays a dead end for the validation, as before turning places existed. One edge per joined
/// street, without polyline; the nodes are the graph's (the ones passed through keep no edge),
/// so node ids, and the SUMO junction the validation matches to each, stay the graph's.
RoadGraph streetsThroughBends(const RoadGraph& graph, const std::vector<char>& node_kind);

}  // namespace slamroute::roadgraph::detail
