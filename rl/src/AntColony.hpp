#pragma once
// Private helper: the upper level of `aco-ga`, an Ant Colony System tour over every directed
// street (paper §3.2.1). Cities are the directed edges of the PlanGraph; the distance from city
// r to city s is the shortest legal drive from having driven r to having driven s, so the tour is
// an asymmetric TSP whose legs obey the turn permissions.
#include <cstdint>
#include <vector>

#include "EdgeDistances.hpp"
#include "slamroute/rl/CoverageConfig.hpp"

namespace slamroute::rl::detail {

struct AntTour {
  std::vector<int> cities;           ///< every directed edge once, in visiting order
  double cost_m = 0.0;               ///< sum of leg distances (plus the return when closed) [m]
  double nearest_neighbour_m = 0.0;  ///< the greedy tour ACS starts its pheromone from [m]
  int improved_at_iteration = 0;     ///< iteration of the last improvement of the best tour
};

/// ACS (state transition rule with exploitation q0, local and global pheromone updates) with
/// candidate lists. Deterministic for a given seed.
AntTour antColonyTour(const EdgeDistances& d, const AntColonyConfig& cfg, std::uint64_t seed);

}  // namespace slamroute::rl::detail
