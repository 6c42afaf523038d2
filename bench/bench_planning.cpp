// Planning time vs graph size (paper Table 3) for qlearning, tsp and postman, on synthetic
// city-like grids (one-way streets, no U-turns) and the real nets; plus route lengths relative
// to postman. Prints markdown tables (bench/RESULTS.md "Planning").
//   bench_planning [--quick] [--no-tsp-above N]
// The real nets Bologna and Ingolstadt are read from ../shared/networks beside the clone (not
// shipped: see networks/README.md); a missing one prints a "missing" row.
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "slamroute/core/Log.hpp"
#include "slamroute/core/RoadGraph.hpp"
#include "slamroute/core/SumoNet.hpp"
#include "slamroute/rl/Planners.hpp"
#include "slamroute/rl/SyntheticGraph.hpp"

using namespace slamroute;

namespace {

struct Run {
  double seconds = 0, length = 0, node_cov = 0, edge_cov = 0, final_logdet = 0, max_logdet = 0,
         mean_logdet = 0, weight = 0;
  int closures = 0;
  int illegal = 0;
  bool heuristic = false, ok = false;
  std::string err;
};

Run runPlanner(const RoadGraph& g, const std::string& planner, const std::string& where) {
  rl::Config cfg;
  cfg.planner = planner;
  Run out;
  try {
    const auto t0 = std::chrono::steady_clock::now();
    const Route r = rl::plan(g, cfg, 42, where);
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    out.length = r.length_m;
    out.node_cov = r.node_coverage_pct;
    out.edge_cov = r.edge_coverage_pct;
    out.heuristic = r.heuristic;
    out.final_logdet = r.final_logdet_cov;
    out.max_logdet = r.max_logdet_cov;
    for (double x : r.logdet_cov_along)
      out.mean_logdet += x / static_cast<double>(r.logdet_cov_along.size());
    out.closures = r.loop_closures;
    out.weight = r.mean_edge_weight;
    out.illegal = nlohmann::json::parse(r.extra_json).value("illegal_turns", -1);
    out.ok = true;
  } catch (const std::exception& e) {
    out.err = e.what();
  }
  return out;
}

std::string cell(const Run& r) {
  if (!r.ok) return "refused";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.3f", r.seconds);
  return buf;
}

/// Planning time against graph size on synthetic grid cities (paper Table 3).
void printGridTimes(bool quick, int tsp_limit) {
  struct Size {
    int rows, cols;
  };
  std::vector<Size> sizes = {{5, 10}, {10, 10}, {20, 25}, {40, 50}};
  if (quick) sizes.resize(2);
  std::printf(
      "## Planning time vs graph size (synthetic grid cities: 100 m blocks, 15 m jitter, "
      "20 %% one-way streets, no U-turns except dead ends, weights in [0.2, 1])\n\n");
  std::printf(
      "| nodes | edges | qlearning s | tsp s (method) | postman s | qlearning / postman length | "
      "qlearning node cov %% | illegal turns (q/t/p) |\n|---|---|---|---|---|---|---|---|\n");
  for (const Size& s : sizes) {
    rl::GridCitySpec spec;
    spec.rows = s.rows;
    spec.cols = s.cols;
    spec.jitter_m = 15.0;
    spec.one_way_fraction = 0.2;
    spec.forbid_u_turns = true;
    spec.weight_min = 0.2;
    spec.seed = 5;
    const RoadGraph g = rl::gridCity(spec);
    const Run q = runPlanner(g, "qlearning", "grid");
    const Run p = runPlanner(g, "postman", "grid");
    Run t;
    const int n = s.rows * s.cols;
    if (n <= tsp_limit)
      t = runPlanner(g, "tsp", "grid");
    else
      t.err = "skipped";
    std::printf("| %d | %zu | %s | %s (%s) | %s | %.2f | %.1f | %d/%d/%d |\n", n, g.edges.size(),
                cell(q).c_str(), t.ok ? cell(t).c_str() : t.err.c_str(),
                t.ok ? (t.heuristic ? "heuristic" : "held-karp") : "-", cell(p).c_str(),
                p.ok && q.ok ? q.length / p.length : 0.0, q.node_cov, q.illegal,
                t.ok ? t.illegal : -1, p.illegal);
    std::fflush(stdout);
  }
}

/// Every planner on the real nets' largest legally drivable part.
void printRealNets() {
  std::printf("\n## Real networks (largest legally drivable part)\n\n");
  std::printf(
      "| net | plan nodes/edges | planner | seconds | length km | / postman | node cov %% | "
      "edge cov %% | illegal turns | loop closures | mean / max log det cov "
      "|\n|---|---|---|---|---|---|---|---|---|---|---|\n");
  const std::filesystem::path shared(SLAMROUTE_SHARED_DIR), src(SLAMROUTE_SOURCE_DIR);
  const std::vector<std::pair<std::string, std::filesystem::path>> nets = {
      {"default_city", src / "networks/default_city/default_city.net.xml"},
      {"bologna_acosta", shared / "networks/bologna_acosta/acosta_buslanes.net.xml"},
      {"ingolstadt21", shared / "networks/ingolstadt21/ingolstadt21.net.xml"}};
  for (const auto& [name, path] : nets) {
    std::fprintf(stderr, "%s\n", name.c_str());
    if (!std::filesystem::exists(path)) {
      std::printf("| %s | missing | | | | | | | | | |\n", name.c_str());
      continue;
    }
    const RoadGraph g = RoadGraph::fromSumoNet(SumoNet::read(path), false);
    const rl::PlanGraph pg = rl::PlanGraph::build(g, name);
    const Run p = runPlanner(g, "postman", name);
    for (const std::string planner : {"qlearning", "random", "tsp", "postman"}) {
      const Run r = planner == "postman" ? p : runPlanner(g, planner, name);
      std::printf("| %s | %d/%d | %s | %s | %.2f | %.2f | %.1f | %.1f | %d | %d | %.2f / %.2f |\n",
                  name.c_str(), pg.n, pg.m, planner.c_str(), cell(r).c_str(), r.length / 1000.0,
                  p.length > 0 ? r.length / p.length : 0.0, r.node_cov, r.edge_cov, r.illegal,
                  r.closures, r.mean_logdet, r.max_logdet);
      std::fflush(stdout);
    }
  }
}

/// What the learning contributes: paper Table 2's rewards against an untrained table.
void printQLearningVariants() {
  std::printf(
      "\n## Q-learning variants on a weighted 12x12 two-way grid (weights uniform in [0.1, "
      "1])\n\n");
  std::printf(
      "| reward | episodes | length km | mean edge weight | edge cov %% | mean / max log det cov | "
      "shortest-path share %% |\n|---|---|---|---|---|---|---|\n");
  rl::GridCitySpec ws;
  ws.rows = ws.cols = 12;
  ws.weight_min = 0.1;
  ws.seed = 9;
  const RoadGraph wg = rl::gridCity(ws);
  for (const std::string reward : {"full", "accuracy"})
    for (int episodes : {1000, 0}) {
      rl::Config cfg;
      cfg.reward = reward;
      cfg.qlearning.episodes = episodes;
      const Route r = rl::plan(wg, cfg, 42, "grid");
      double mean = 0.0;
      for (double x : r.logdet_cov_along)
        mean += x / static_cast<double>(r.logdet_cov_along.size());
      const double sp = nlohmann::json::parse(r.extra_json).value("shortest_path_length_m", 0.0);
      std::printf("| %s | %d | %.2f | %.3f | %.1f | %.2f / %.2f | %.0f |\n", reward.c_str(),
                  episodes, r.length_m / 1000.0, r.mean_edge_weight, r.edge_coverage_pct, mean,
                  r.max_logdet_cov, 100.0 * sp / r.length_m);
    }
}

}  // namespace

int main(int argc, char** argv) {
  setLogLevel(LogLevel::Error);
  bool quick = false;
  int tsp_limit = 2000;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--quick")) quick = true;
    if (!std::strcmp(argv[i], "--no-tsp-above") && i + 1 < argc) tsp_limit = std::atoi(argv[++i]);
  }
  printGridTimes(quick, tsp_limit);
  printRealNets();
  printQLearningVariants();
  return 0;
}
