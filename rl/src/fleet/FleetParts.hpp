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
  std::string start;  ///< partition: kmeans | sweep | sweep back | circuit legs (the best)
};

/// Per vehicle: its closed route (local edge ids) from and back to its depot.
/// partition: the best of four starting partitions (K-means on the street midpoints; sectors
/// around the first depot, swept either way round; the circuit's legs, circuitLegParts), each
/// improved by the balancing moves (single streets, merge-splits) and kicks.
std::vector<std::vector<int>> partitionRoutes(const FleetContext& ctx, const FleetConfig& cfg,
                                              std::uint64_t seed, const std::vector<int>& circuit,
                                              StrategyStats& stats);
std::vector<std::vector<int>> splitCircuitRoutes(const FleetContext& ctx,
                                                 const std::vector<int>& circuit,
                                                 StrategyStats& stats);

/// Per directed edge: the vehicle whose leg (as splitCircuitRoutes cuts and assigns them)
/// drives it first along the circuit; -1 for none.
std::vector<int> circuitLegParts(const FleetContext& ctx, const std::vector<int>& circuit);

/// part_of_edge with the edges of parts p and q re-split between them: both parts' streets as
/// one rural postman tour from p's depot, cut into two legs like circuitLegParts (MergeSplit.cpp).
/// A part may come back empty. `solves`, when given, grows by the circulations solved.
std::vector<int> mergeSplitParts(const FleetContext& ctx, const std::vector<int>& part_of_edge,
                                 int p, int q, int* solves = nullptr);

/// part_of_edge with the edges of parts p and q given to p or q as `tour` (a closed walk from
/// p's depot driving all of them) is best cut into two legs.
std::vector<int> splitTourParts(const FleetContext& ctx, const std::vector<int>& part_of_edge,
                                int p, int q, const std::vector<int>& tour);

/// Per vehicle i and column j: the cost of giving column j to vehicle i; returns per vehicle
/// its column (Hungarian, rows = vehicles, every vehicle gets one when columns >= vehicles).
std::vector<int> assignToVehicles(const std::vector<std::vector<double>>& cost);

}  // namespace slamroute::rl::fleet
