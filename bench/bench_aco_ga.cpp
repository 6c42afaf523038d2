// Gong & Lee's Tables 1-3 on grid worlds like their environments A and B: total length,
// condition satisfied (C_k <= C_threshold all along), planning time per cycle, coverage legs and
// loop-closure revisits, C_average; mean +- sd over seeds. Then planning time of aco-ga on a
// 500-junction city-like grid (bench/RESULTS.md).
//   bench_aco_ga [--seeds N] [--skip-large]
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "slamroute/core/Log.hpp"
#include "slamroute/rl/Planners.hpp"
#include "slamroute/rl/SyntheticGraph.hpp"

using namespace slamroute;

namespace {

struct Stat {
  std::vector<double> v;
  void add(double x) { v.push_back(x); }
  std::string str(int prec) const {
    double m = 0, s = 0;
    for (double x : v) m += x / static_cast<double>(v.size());
    for (double x : v) s += (x - m) * (x - m);
    s = v.size() > 1 ? std::sqrt(s / static_cast<double>(v.size() - 1)) : 0.0;
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f ± %.*f", prec, m, prec, s);
    return buf;
  }
};

struct Row {
  Stat length, seconds, legs, revisits, c_avg, c_max;
  int satisfied = 0, runs = 0;
};

struct Env {
  const char* name;
  rl::GridCitySpec spec;
  double threshold_m2;
};

const char* kPlanners[] = {"open-loop", "exhaustive-revisit", "switching", "aco-ga"};

Row runPlanner(const RoadGraph& g, const char* planner, double threshold, int seeds) {
  Row row;
  for (int seed = 1; seed <= seeds; ++seed) {
    rl::Config cfg;
    cfg.planner = planner;
    cfg.coverage.c_threshold_m2 = threshold;
    cfg.eif = rl::gridWorldNoise();  // the paper-like environments' bounds were set for it
    const Route r = rl::plan(g, cfg, static_cast<std::uint64_t>(seed), "grid");
    const auto x = nlohmann::json::parse(r.extra_json);
    row.length.add(r.length_m);
    row.seconds.add(r.planning_seconds);
    row.legs.add(x["coverage_legs"].get<double>());
    row.revisits.add(x["loop_closure_revisits"].get<double>());
    row.c_avg.add(x["uncertainty"]["c_average_m2"].get<double>());
    row.c_max.add(x["uncertainty"]["c_max_m2"].get<double>());
    row.satisfied += x["uncertainty"]["bound_satisfied"].get<bool>() ? 1 : 0;
    ++row.runs;
  }
  return row;
}

void tables(const std::vector<Env>& envs, int seeds) {
  std::printf(
      "| env | method | l_total [m] | condition satisfied | T_cycle [s] | n(N) legs | "
      "n(N_loop) revisits | C_average [m^2] | C_max [m^2] "
      "|\n|---|---|---|---|---|---|---|---|---|\n");
  for (const Env& env : envs) {
    const RoadGraph g = rl::gridCity(env.spec);
    for (const char* p : kPlanners) {
      const Row r = runPlanner(g, p, env.threshold_m2, seeds);
      std::printf("| %s | %s | %s | %d / %d | %s | %s | %s | %s | %s |\n", env.name, p,
                  r.length.str(0).c_str(), r.satisfied, r.runs, r.seconds.str(3).c_str(),
                  r.legs.str(1).c_str(), r.revisits.str(1).c_str(), r.c_avg.str(2).c_str(),
                  r.c_max.str(1).c_str());
    }
  }
}

void largeGrid() {
  rl::GridCitySpec s;
  s.rows = 20;
  s.cols = 25;
  s.jitter_m = 15.0;
  s.one_way_fraction = 0.2;
  s.forbid_u_turns = true;
  s.weight_min = 0.2;
  s.seed = 1;
  const RoadGraph g = rl::gridCity(s);
  std::printf(
      "\n| planner | nodes | directed edges | planning [s] | distances [s] | ACO [s] | length [km] "
      "| postman lower bound [km] |\n|---|---|---|---|---|---|---|---|\n");
  for (const char* p : {"open-loop", "aco-ga"}) {
    rl::Config cfg;
    cfg.planner = p;
    const auto t0 = std::chrono::steady_clock::now();
    const Route r = rl::plan(g, cfg, 1, "grid");
    const double secs =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const auto x = nlohmann::json::parse(r.extra_json);
    std::printf("| %s | %d | %d | %.2f | %.2f | %.2f | %.2f | %.2f |\n", p,
                x["plan_graph"]["nodes"].get<int>(), x["plan_graph"]["edges"].get<int>(), secs,
                x["seconds"]["distances"].get<double>(), x["seconds"]["aco"].get<double>(),
                r.length_m / 1000.0, rl::turnFreePostmanLength(rl::PlanGraph::build(g)) / 1000.0);
  }
}

}  // namespace

int main(int argc, char** argv) {
  setLogLevel(LogLevel::Error);
  int seeds = 5;
  bool large = true;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--seeds") && i + 1 < argc) seeds = std::atoi(argv[++i]);
    if (!std::strcmp(argv[i], "--skip-large")) large = false;
  }
  rl::GridCitySpec a;  // A: 3 x 4 junctions, 100 m blocks (34 directed streets)
  a.rows = 3;
  a.cols = 4;
  rl::GridCitySpec b;  // B: 4 x 5 junctions, 50 m blocks (62 directed streets)
  b.rows = 4;
  b.cols = 5;
  b.spacing_m = 50.0;
  tables({{"A, C_th 15", a, 15.0},
          {"A, C_th 20", a, 20.0},
          {"B, C_th 5", b, 5.0},
          {"B, C_th 10", b, 10.0}},
         seeds);
  if (large) largeGrid();
  return 0;
}
