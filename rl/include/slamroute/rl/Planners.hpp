#pragma once
// The planners (paper §3.2 and baselines) and the top-level entry `plan()` that turns a road
// graph into a core Route with its metrics.
#include <cstdint>
#include <string>
#include <vector>

#include "slamroute/core/RoadGraph.hpp"
#include "slamroute/core/Route.hpp"
#include "slamroute/rl/Config.hpp"
#include "slamroute/rl/PlanGraph.hpp"
#include "slamroute/rl/PlannerStats.hpp"

namespace slamroute::rl {

/// What a planner returns, in PlanGraph-local edge ids.
struct PlanOutput {
  std::vector<int> edges;                    ///< edge sequence, the first leaves the start node
  bool heuristic = false;                    ///< optimality not guaranteed
  bool completed_by_shortest_paths = false;  ///< finished by shortest paths after a stall / cap
  std::string notes;
  PlannerStats stats;  ///< the planner family's own figures
};

/// Coverage goal of an episode / a route: every node visited, or every street driven.
enum class Goal { Nodes, Edges };
Goal parseGoal(const std::string& name);  ///< "nodes" | "edges"; throws std::invalid_argument

PlanOutput planQLearning(const PlanGraph& pg, const TurnPaths& paths, const Config& cfg, int start,
                         std::uint64_t seed);
PlanOutput planRandom(const PlanGraph& pg, const TurnPaths& paths, const Config& cfg, int start,
                      std::uint64_t seed);
PlanOutput planTsp(const PlanGraph& pg, const TurnPaths& paths, const Config& cfg, int start);
PlanOutput planPostman(const PlanGraph& pg, const TurnPaths& paths, const Config& cfg, int start);

/// aco-ga | open-loop | exhaustive-revisit | switching (CoverageConfig.hpp, Uncertainty.hpp).
bool isCoveragePlanner(const std::string& planner);
PlanOutput planCoverage(const PlanGraph& pg, const TurnPaths& paths, const Config& cfg, int start,
                        std::uint64_t seed);

/// Optimal directed Chinese postman length ignoring turn permissions (a lower bound for any
/// route driving every edge) [m].
double turnFreePostmanLength(const PlanGraph& pg);

/// Exact Held-Karp DP over a distance matrix d[i][j] (asymmetric allowed). Returns the visiting
/// order starting with `start` (closed: cost includes the return to start). Throws
/// std::invalid_argument above 22 nodes (memory 2^(n-1)*(n-1)*9 bytes).
std::vector<int> heldKarp(const std::vector<std::vector<double>>& d, int start, bool closed,
                          double* cost = nullptr);

/// Number of consecutive edge pairs (e, f) in `edges` that are not allowed turns.
int countIllegalTurns(const PlanGraph& pg, const std::vector<int>& edges);

/// Fills the metrics of `route` (ids mapped back to the RoadGraph) for a local edge sequence:
/// nodes, edges, SUMO edges, length, coverage, revisits, loop closures, mean weight, EIF log-det.
void fillRouteMetrics(const PlanGraph& pg, const RoadGraph& g, int start,
                      const std::vector<int>& edges, const EifConfig& eif, Route& route);

/// The whole planning step: builds the PlanGraph (largest legally drivable part; logs a warning
/// naming `where` when parts were dropped), resolves the start node (cfg.start_node, RoadGraph
/// id, -1 = first node), runs cfg.planner and returns the route with its metrics.
/// Throws std::invalid_argument on an empty graph, an unknown planner or an unreachable start.
Route plan(const RoadGraph& g, const Config& cfg, std::uint64_t seed,
           const std::string& where = "graph");

}  // namespace slamroute::rl
