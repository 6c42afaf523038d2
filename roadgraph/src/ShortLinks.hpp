#pragma once
// Internal to roadgraph: vehicles' drives from one junction to the next, for links between close
// junctions whose street lies inside the cleared node neighbourhoods (paper §3.1 step 2 removes
// it with them) and for the direction of travel on short streets. See ShortLinks.cpp.
#include <map>
#include <tuple>
#include <vector>

#include "slamroute/core/Types.hpp"
#include "slamroute/roadgraph/Config.hpp"
#include "slamroute/roadgraph/Traces.hpp"

namespace slamroute::roadgraph::detail {

/// (from node, to node, street between or -1) -> number of vehicles that drove it.
using Passages = std::map<std::tuple<int, int, int>, int>;

/// Drives between intersection nodes (`nodes[0, n_inter)`): a vehicle passes a junction when it
/// comes within edges.link_visit_m of its node; consecutive passes through two different
/// junctions, with no time gap > max_gap_s and the points of at most one street
/// (`street_of_point`, -1 = none) in between, are one drive along that street (or along no
/// street). `order`: trace point indices sorted by vehicle, then time.
Passages junctionPassages(const Traces& traces, const std::vector<std::size_t>& order,
                          const std::vector<int>& street_of_point, const std::vector<Point3>& nodes,
                          std::size_t n_inter, const EdgeConfig& ec, double half_height_m);

}  // namespace slamroute::roadgraph::detail
