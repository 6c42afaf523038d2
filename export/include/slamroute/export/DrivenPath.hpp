#pragma once
// The polyline a route drives: its SUMO edges' centre-lane shapes end to end.
#include <string>
#include <vector>

#include "slamroute/core/SumoNet.hpp"
#include "slamroute/core/Types.hpp"

namespace slamroute::exports {

struct DrivenPath {
  Polyline points;                      ///< net x/y/z, consecutive duplicates dropped
  std::vector<std::size_t> edge_first;  ///< per route edge: index of its first point in `points`
  std::vector<double> edge_start_m;     ///< per route edge: distance driven before it [m]
  std::vector<double> edge_length_m;    ///< per route edge: its shape's length [m]
  double length_m = 0.0;
};

/// Throws std::invalid_argument naming the net when a SUMO edge is not in it.
DrivenPath drivenPath(const SumoNet& net, const std::vector<std::string>& sumo_edges);

}  // namespace slamroute::exports
