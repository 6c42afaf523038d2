#pragma once
// What a route covers of a SUMO net, counted the way a survey crew counts streets: each travel
// direction is its own edge (a two-way street driven one way is half covered), over the part of
// the net a passenger car can drive round (passenger edges of the largest strongly connected
// part; internal junction edges excluded). And the route's length as SUMO drives it: its edges
// plus the internal junction lanes that join consecutive edges.
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <vector>

#include "slamroute/core/SumoNet.hpp"

namespace slamroute {

struct SumoCoverage {
  int edges_driven = 0, edges_total = 0;     ///< drivable directed SUMO edges
  double length_driven_m = 0.0;              ///< their length, each edge once [m]
  double length_total_m = 0.0;               ///< length of every drivable edge [m]
  double edges_pct = 0.0, length_pct = 0.0;  ///< driven / total [%]
  double route_on_edges_m = 0.0;             ///< route's SUMO edges, repeats counted [m]
  double route_in_junctions_m = 0.0;         ///< internal lanes between them [m]
  int turns_without_connection = 0;          ///< consecutive pairs SUMO does not join

  double routeLengthM() const { return route_on_edges_m + route_in_junctions_m; }
};

/// Directed coverage and SUMO length of the edge sequence `route` (ids of normal edges; ids the
/// net does not have or internal ids starting with ':' are skipped, consecutive repeats merged).
/// Throws std::invalid_argument naming the net when it has no drivable edge.
SumoCoverage sumoCoverage(const SumoNet& net, const std::vector<std::string>& route);

/// The "directed_coverage" and "sumo_length" objects of route.json and metrics.json, set in `j`.
void sumoCoverageToJson(const SumoCoverage& c, nlohmann::json& j);
/// Back from them; nullopt when `j` has none. Throws nlohmann::json::exception on wrong types.
std::optional<SumoCoverage> sumoCoverageFromJson(const nlohmann::json& j);

}  // namespace slamroute
