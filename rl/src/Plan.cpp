// plan(): planning graph, start node, planner dispatch, metrics.
#include <chrono>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "PlannerStatsJson.hpp"
#include "slamroute/core/Log.hpp"
#include "slamroute/rl/Planners.hpp"
#include "slamroute/rl/Uncertainty.hpp"

namespace slamroute::rl {

Goal parseGoal(const std::string& name) {
  if (name == "nodes") return Goal::Nodes;
  if (name == "edges") return Goal::Edges;
  throw std::invalid_argument("rl.goal: unknown goal '" + name + "' (expected nodes or edges)");
}

namespace {

/// C_k along the route (Uncertainty.hpp) against rl.coverage.c_threshold_m2, for every planner.
nlohmann::json uncertaintyJson(const PlanGraph& pg, const Config& cfg, int start,
                               const std::vector<int>& edges) {
  const UncertaintySeries s = predictUncertainty(pg, cfg.eif, start, edges);
  const double bound = cfg.coverage.c_threshold_m2;
  return {{"definition", "C_k = sqrt(det EIF position covariance) after each edge [m^2]"},
          {"c_threshold_m2", bound},
          {"c_max_m2", s.max_m2},
          {"c_average_m2", s.mean_m2},
          {"bound_satisfied", s.max_m2 <= bound},
          {"closures", s.closures},
          {"c_along_m2", s.c_m2}};
}

void checkSettings(const Config& cfg) {
  const std::string& p = cfg.planner;
  if (p != "qlearning" && p != "random" && p != "tsp" && p != "postman" && !isCoveragePlanner(p))
    throw std::invalid_argument("unknown planner '" + p +
                                "' (expected qlearning, random, tsp, postman, aco-ga, open-loop, "
                                "exhaustive-revisit or switching)");
  if (isCoveragePlanner(p)) cfg.coverage.validate();
  if (cfg.reward != "full" && cfg.reward != "accuracy")
    throw std::invalid_argument("unknown reward '" + cfg.reward + "' (expected full or accuracy)");
  parseGoal(cfg.goal);
}

/// The start node in the planning graph's numbering (its node 0 unless cfg.start_node is set).
int localStart(const RoadGraph& g, const PlanGraph& pg, const Config& cfg,
               const std::string& where) {
  if (cfg.start_node < 0) return 0;
  if (cfg.start_node >= static_cast<int>(g.nodes.size()))
    throw std::invalid_argument(where + ": start node " + std::to_string(cfg.start_node) +
                                " does not exist (the graph has " + std::to_string(g.nodes.size()) +
                                " nodes)");
  const int start = pg.node_local[static_cast<std::size_t>(cfg.start_node)];
  if (start < 0)
    throw std::invalid_argument(
        where + ": start node " + std::to_string(cfg.start_node) +
        " is unreachable (outside the largest part that is strongly connected under the turn "
        "permissions)");
  return start;
}

PlanOutput runPlanner(const PlanGraph& pg, const TurnPaths& paths, const Config& cfg, int start,
                      std::uint64_t seed) {
  const std::string& p = cfg.planner;
  if (p == "qlearning") return planQLearning(pg, paths, cfg, start, seed);
  if (p == "random") return planRandom(pg, paths, cfg, start, seed);
  if (p == "tsp") return planTsp(pg, paths, cfg, start);
  if (p == "postman") return planPostman(pg, paths, cfg, start);
  return planCoverage(pg, paths, cfg, start, seed);
}

/// route.json's "extra": the planner's own figures plus the planning graph and the route's checks.
std::string extraJson(const RoadGraph& g, const PlanGraph& pg, const Config& cfg, int start,
                      const PlanOutput& out) {
  nlohmann::json extra = plannerStatsJson(out.stats);
  extra["goal"] = cfg.goal;
  if (cfg.planner == "qlearning") extra["reward"] = cfg.reward;
  extra["plan_graph"] = {{"nodes", pg.n},
                         {"edges", pg.m},
                         {"dropped_nodes", pg.dropped_nodes},
                         {"dropped_edges", pg.dropped_edges},
                         {"turn_restricted", pg.restricted},
                         {"total_edge_length_m", pg.total_edge_len}};
  extra["illegal_turns"] = countIllegalTurns(pg, out.edges);
  extra["uncertainty"] = uncertaintyJson(pg, cfg, start, out.edges);
  int without_sumo = 0;
  for (int e : out.edges)
    without_sumo += g.edges[static_cast<std::size_t>(pg.edge_orig[static_cast<std::size_t>(e)])]
                        .sumo_edges.empty();
  extra["edges_without_sumo"] = without_sumo;
  extra["start_node"] = pg.node_orig[static_cast<std::size_t>(start)];
  return extra.dump();
}

}  // namespace

Route plan(const RoadGraph& g, const Config& cfg, std::uint64_t seed, const std::string& where) {
  checkSettings(cfg);
  const auto t0 = std::chrono::steady_clock::now();
  const PlanGraph pg = PlanGraph::build(g, where);
  if (pg.dropped_nodes > 0 || pg.dropped_edges > 0)
    logWarn(where +
            ": not strongly connected under its turn permissions; planning on the largest "
            "part (" +
            std::to_string(pg.n) + " nodes, " + std::to_string(pg.m) + " edges; dropped " +
            std::to_string(pg.dropped_nodes) + " nodes, " + std::to_string(pg.dropped_edges) +
            " edges)");
  const int start = localStart(g, pg, cfg, where);
  const TurnPaths paths(pg);
  const PlanOutput out = runPlanner(pg, paths, cfg, start, seed);
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  Route r;
  r.planner = cfg.planner;
  r.seed = seed;
  fillRouteMetrics(pg, g, start, out.edges, cfg.eif, r);
  r.planning_seconds = secs;
  r.heuristic = out.heuristic;
  r.completed_by_shortest_paths = out.completed_by_shortest_paths;
  r.notes = out.notes;
  r.extra_json = extraJson(g, pg, cfg, start, out);
  return r;
}

}  // namespace slamroute::rl
