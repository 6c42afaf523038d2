#pragma once
// Private to the fleet planner: what its two strategies share, and the strategies.
#include <cstdint>
#include <string>
#include <vector>

#include "slamroute/core/RoadGraph.hpp"
#include "slamroute/rl/FleetConfig.hpp"
#include "slamroute/rl/PlanGraph.hpp"

namespace slamroute::rl::fleet {

/// The planning graph, its legal paths and each vehicle's depot with its legal distances.
struct FleetContext {
  const RoadGraph& g;
  const PlanGraph& pg;
  const TurnPaths& paths;
  std::vector<int> depot;                       ///< per vehicle: local node
  std::vector<std::vector<double>> from_depot;  ///< per vehicle, per edge: depot -> driven edge [m]
  std::vector<std::vector<double>> to_depot;    ///< per vehicle, per edge: after edge -> depot [m]
  int vehicles() const { return static_cast<int>(depot.size()); }
};

FleetContext makeContext(const RoadGraph& g, const PlanGraph& pg, const TurnPaths& paths,
                         std::vector<int> depot_local);

/// Figures of a strategy for route.json.
struct StrategyStats {
  double makespan_before_moves_m = 0.0;  ///< partition: before the balancing moves
  int balance_moves = 0;                 ///< partition: street moves applied
  int legs = 0;                          ///< postman: legs the circuit was cut into
  std::string start;                     ///< partition: kmeans | sweep | circuit legs (the best)
};

/// Per vehicle: its closed route (local edge ids) from and back to its depot.
/// partition: the best of three starting partitions (K-means on the street midpoints; sectors
/// around the first depot; the circuit's legs, circuitLegParts), each improved by the balancing
/// moves and kicks.
std::vector<std::vector<int>> partitionRoutes(const FleetContext& ctx, const FleetConfig& cfg,
                                              std::uint64_t seed, const std::vector<int>& circuit,
                                              StrategyStats& stats);
std::vector<std::vector<int>> splitCircuitRoutes(const FleetContext& ctx,
                                                 const std::vector<int>& circuit,
                                                 StrategyStats& stats);

/// Per directed edge: the vehicle whose leg (as splitCircuitRoutes cuts and assigns them)
/// drives it first along the circuit; -1 for none.
std::vector<int> circuitLegParts(const FleetContext& ctx, const std::vector<int>& circuit);

/// Per vehicle i and column j: the cost of giving column j to vehicle i; returns per vehicle
/// its column (Hungarian, rows = vehicles, every vehicle gets one when columns >= vehicles).
std::vector<int> assignToVehicles(const std::vector<std::vector<double>>& cost);

}  // namespace slamroute::rl::fleet
