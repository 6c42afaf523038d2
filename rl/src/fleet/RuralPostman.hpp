#pragma once
// Private to the fleet planner: a legal closed route from a depot that drives a required subset
// of the streets (directed rural postman under SUMO's turn permissions), and the legal distances
// the fleet's bounds and assignments need.
#include <vector>

#include "slamroute/rl/PlanGraph.hpp"

namespace slamroute::rl::fleet {

/// Edges from the node state of `depot` back to `depot` that drive every edge e with
/// required[e] != 0, each consecutive pair an allowed turn. Empty when nothing is required.
/// Throws std::runtime_error when a required edge cannot be reached and left legally.
/// `solves`, when given, grows by the min-cost circulations solved (what the route costs).
std::vector<int> ruralPostmanRoute(const PlanGraph& pg, const TurnPaths& paths,
                                   const std::vector<char>& required, int depot,
                                   int* solves = nullptr);

/// Per edge e: the shortest legal length driven after e until arriving at `node` (0 when e ends
/// there; +inf when it cannot). The reverse of TurnPaths::distances.
std::vector<double> distancesToNode(const PlanGraph& pg, int node);

/// Sum of edge lengths [m].
double routeLength(const PlanGraph& pg, const std::vector<int>& edges);

}  // namespace slamroute::rl::fleet
