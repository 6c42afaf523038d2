#pragma once
// What a route covers of a SUMO net, counted the way a survey crew counts streets: each travel
// direction is its own edge (a two-way street driven one way is half covered), over the part of
// the net a passenger car can drive round legally (passenger edges of the largest part strongly
// connected under SUMO's turn permissions; internal junction edges excluded). Beside it, the
// same over the junction-level part (largest strongly connected part over junctions, turns
// ignored), which also holds edges no legal drive enters and leaves again (a two-way street to
// the map border where cars may not turn round): they are counted, not hidden. And the route's
// length as SUMO drives it: its edges plus the internal junction lanes that join consecutive
// edges.
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <vector>

#include "slamroute/core/SumoNet.hpp"

namespace slamroute {

struct SumoCoverage {
  int edges_driven = 0, edges_total = 0;     ///< directed SUMO edges of the legal part
  double length_driven_m = 0.0;              ///< their length, each edge once [m]
  double length_total_m = 0.0;               ///< length of every drivable edge [m]
  double edges_pct = 0.0, length_pct = 0.0;  ///< driven / total [%]
  /// The junction-level part: its edges, those driven, and those without a legal drive round.
  int junction_part_edges = 0, junction_part_driven = 0, edges_without_legal_route = 0;
  double junction_part_pct = 0.0;     ///< junction_part_driven / junction_part_edges [%]
  double route_on_edges_m = 0.0;      ///< route's SUMO edges, repeats counted [m]
  double route_in_junctions_m = 0.0;  ///< internal lanes between them [m]
  int turns_without_connection = 0;   ///< consecutive pairs SUMO does not join

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
