#pragma once
// Several mapping vehicles share a city: every directed street is driven by at least one of K
// vehicles, each on a legal closed route from its depot, with the longest route (the makespan)
// as short as the strategy finds.
//  - partition: K-means on the street midpoints (weighted by length) splits the streets into K
//    parts; the Hungarian algorithm assigns parts to vehicles (cost: the round trip from the
//    vehicle's depot to the part); each vehicle drives a rural postman route of its part; then
//    boundary streets move from the longest route to a neighbouring part while that shortens
//    the makespan, then merge-splits (two neighbouring parts driven as one tour and cut again
//    in two) while they shorten the routes or even them out. The same from three more starts
//    (sectors of the streets around the first depot, swept either way round; the streets of
//    the postman strategy's legs); the shortest makespan is kept.
//  - postman: the single-vehicle postman circuit cut into K consecutive legs (the cut points
//    minimise the longest leg including its trips from and back to the depot), legs assigned
//    to vehicles by the Hungarian algorithm.
#include <cstdint>
#include <string>
#include <vector>

#include "slamroute/core/FleetRoute.hpp"
#include "slamroute/core/RoadGraph.hpp"
#include "slamroute/rl/Config.hpp"

namespace slamroute::rl {

/// Plans cfg.fleet.vehicles routes. depot_nodes: road-graph node ids, none (cfg.start_node, or
/// the first node of the planning graph, for all), one shared by all, or one per vehicle.
/// Throws std::invalid_argument on a bad vehicle count, strategy or depot (naming `where`).
FleetRoute planFleet(const RoadGraph& g, const Config& cfg, const std::vector<int>& depot_nodes,
                     std::uint64_t seed, const std::string& where = "graph");

}  // namespace slamroute::rl
