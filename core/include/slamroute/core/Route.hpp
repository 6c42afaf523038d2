#pragma once
// A planned route and its file formats: route.json and, when SUMO edges are known, a SUMO
// route file (.rou.xml) with one vehicle driving it.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "slamroute/core/SumoCoverage.hpp"

namespace slamroute {

struct Route {
  std::string planner;  ///< qlearning, random, tsp, postman, manual
  std::uint64_t seed = 0;
  std::vector<int> nodes;               ///< road-graph node sequence
  std::vector<int> edges;               ///< road-graph edge sequence
  std::vector<std::string> sumo_edges;  ///< SUMO edge sequence (drivable), when known
  double length_m = 0.0;
  double node_coverage_pct = 0.0;  ///< share of nodes visited [%]
  double edge_coverage_pct = 0.0;  ///< two-way, graph: share of street length driven [%]
  /// Directed coverage of the net's drivable SUMO edges and the length SUMO drives (the primary
  /// figures), known when the route was checked against the net.
  std::optional<SumoCoverage> sumo_coverage;
  int revisits = 0;                      ///< arrivals at already-visited nodes
  int loop_closures = 0;                 ///< predicted loop closures (revisits after a cycle)
  double mean_edge_weight = 0.0;         ///< length-weighted mean weight driven
  double final_logdet_cov = 0.0;         ///< EIF pose covariance log-det at the end
  double max_logdet_cov = 0.0;           ///< max along the route
  std::vector<double> logdet_cov_along;  ///< per edge step
  double planning_seconds = 0.0;
  bool heuristic = false;  ///< true when the planner's optimality is not guaranteed
  bool completed_by_shortest_paths = false;  ///< qlearning roll-out finished by shortest paths
  std::string notes;
  std::string extra_json = "{}";  ///< planner-specific details (JSON object)

  /// Reads route.json. Also accepts a plain JSON list of SUMO edge ids, or {"sumo_edges":[…]}.
  static Route readJson(const std::filesystem::path& path);
  void writeJson(const std::filesystem::path& path) const;
  /// SUMO route file: <routes><vehicle id="mapper" depart="0"><route edges="…"/></vehicle>.
  void writeRouXml(const std::filesystem::path& path,
                   const std::string& vehicle_id = "mapper") const;
};

}  // namespace slamroute
