#pragma once
// Turning a sequence of SUMO edges into one SUMO can drive: where two consecutive edges are not
// joined by a passenger <connection> (a route planned on a trace-built graph, whose turns are
// unrestricted, can contain a forbidden turn or a gap), the shortest legal detour is inserted.
// A route edge that no legal path reaches or leaves (outside the largest strongly connected part
// of the net, e.g. a street leading out of the map that the survey traces turned around on) is
// dropped from the middle of the route.
#include <string>
#include <vector>

#include "slamroute/core/SumoNet.hpp"

namespace slamroute {

struct LegalRoute {
  std::vector<std::string> edges;  ///< drivable sequence
  int repaired_transitions = 0;    ///< consecutive pairs that needed a detour
  double added_length_m = 0.0;     ///< length of the inserted detour edges [m]
  int dropped_edges = 0;           ///< route edges removed because no legal path passes them
};

/// Repairs `edges` as described above (consecutive duplicates are merged). Throws
/// std::invalid_argument naming the edge when it is missing from the net, is not open to
/// passenger cars, or no legal path joins two consecutive edges (after dropping the ones above).
LegalRoute legalizeSumoRoute(const SumoNet& net, const std::vector<std::string>& edges);

/// Index of the first consecutive pair (i, i+1) SUMO does not allow, or -1 when all are legal.
int firstIllegalTurn(const SumoNet& net, const std::vector<std::string>& edges);

}  // namespace slamroute
