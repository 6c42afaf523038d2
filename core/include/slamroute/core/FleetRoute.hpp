#pragma once
// The routes of a fleet (several mapping vehicles sharing the streets) and their files:
// route.json {"fleet": {summary}, "vehicles": [one route object per vehicle]} and a SUMO route
// file with one vehicle per route (mapper_0, mapper_1, ...).
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "slamroute/core/Route.hpp"

namespace slamroute {

struct FleetRoute {
  std::string strategy;  ///< partition | postman
  std::uint64_t seed = 0;
  std::vector<Route> vehicles;        ///< one closed route per vehicle, from its depot
  std::vector<int> depot_nodes;       ///< per vehicle: road-graph node it leaves and returns to
  double makespan_m = 0.0;            ///< longest vehicle route
  double total_length_m = 0.0;        ///< sum of the vehicle routes
  double balance = 0.0;               ///< makespan / mean route length (1 = perfectly even)
  double single_route_m = 0.0;        ///< L1: the single-vehicle postman route from depot 0
  double longest_round_trip_m = 0.0;  ///< max over edges of the shortest depot-edge-depot trip
  double lower_bound_m = 0.0;         ///< max(L1 / K, longest_round_trip_m)
  /// A proven lower bound that counts every vehicle's drive from its depot and back:
  /// max(longest_round_trip_m, max over far sets F of a + b + L(F) / K, the min-cost flow bound
  /// that adds the detours between far streets; rl MakespanBound.cpp, FlowBound.cpp)
  double depot_bound_m = 0.0;
  double edge_coverage_pct = 0.0;       ///< directed drivable edges driven by some vehicle [%]
  double sumo_edge_coverage_pct = 0.0;  ///< directed SUMO edges driven by some vehicle [%]
  double planning_seconds = 0.0;
  std::string extra_json = "{}";  ///< strategy-specific figures (JSON object)

  /// True when `path` is a JSON object with a "vehicles" list (a fleet's route.json).
  static bool isFleetFile(const std::filesystem::path& path);
  /// Throws std::invalid_argument naming the file on malformed input or an empty fleet.
  static FleetRoute readJson(const std::filesystem::path& path);
  void writeJson(const std::filesystem::path& path) const;
  /// Vehicles mapper_0..mapper_{K-1}, all departing at 0 (SUMO inserts them as space allows).
  void writeRouXml(const std::filesystem::path& path) const;
  static std::string vehicleId(std::size_t index) { return "mapper_" + std::to_string(index); }
};

}  // namespace slamroute
