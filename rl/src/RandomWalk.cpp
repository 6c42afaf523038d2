// `random`: a uniform random walk over the allowed turns until the goal is met (paper Table 1's
// "random route"). Capped at random.max_steps_per_edge * edges, then finished by shortest paths.
// With random.budget_m > 0 the walk stops once it has driven that far, goal met or not: a
// mapping crew has a fixed driving budget, and Table 1 compares routes of equal length.
#include <random>

#include "Coverage.hpp"
#include "slamroute/rl/Planners.hpp"

namespace slamroute::rl {

PlanOutput planRandom(const PlanGraph& pg, const TurnPaths& paths, const Config& cfg, int start,
                      std::uint64_t seed) {
  detail::Coverage cov(pg, parseGoal(cfg.goal), start);
  std::mt19937_64 rng(seed);
  PlanOutput out;
  const long long cap = static_cast<long long>(cfg.random.max_steps_per_edge * pg.m) + 1;
  const double budget = cfg.random.budget_m > 0.0 ? cfg.random.budget_m : 1e300;
  double driven = 0.0;
  int cur_edge = -1;
  for (long long step = 0; step < cap && !cov.done() && driven < budget; ++step) {
    const int b = cur_edge < 0 ? pg.outBegin(start) : pg.nextBegin(cur_edge);
    const int e = cur_edge < 0 ? pg.outEnd(start) : pg.nextEnd(cur_edge);
    const std::vector<int>& acts = cur_edge < 0 ? pg.out : pg.next;
    const int f = acts[static_cast<std::size_t>(
        b + static_cast<int>(rng() % static_cast<std::uint64_t>(e - b)))];
    cov.drive(f);
    out.edges.push_back(f);
    driven += pg.len[static_cast<std::size_t>(f)];
    cur_edge = f;
  }
  double extra = 0.0;
  int segments = 0;
  if (!cov.done() && driven >= budget) {
    out.notes = "random walk stopped at its length budget of " +
                std::to_string(static_cast<int>(cfg.random.budget_m)) +
                " m before meeting the goal";
  } else if (!cov.done()) {
    segments = detail::completeByShortestPaths(pg, paths, cov, start, out.edges, &extra);
    out.completed_by_shortest_paths = true;
    out.notes = "random walk hit its step cap; finished by shortest paths";
  }
  out.heuristic = true;
  out.stats = RandomWalkStats{segments, extra};
  return out;
}

}  // namespace slamroute::rl
