// `aco-ga` (Gong & Lee §3.2: ant colony coverage tour, then a genetic algorithm placing
// loop-closure revisits under a bound on C_k) and the paper's baselines on the same tour:
// `open-loop` (no revisits), `exhaustive-revisit` (a revisit after every coverage leg but the
// last), `switching` (a revisit when going on would break the bound). All cover every directed
// street of the PlanGraph with legal turns; C_k is defined in Uncertainty.hpp.
#include <chrono>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "AntColony.hpp"
#include "GeneticRevisits.hpp"
#include "RevisitWalk.hpp"
#include "slamroute/rl/Planners.hpp"

namespace slamroute::rl {

namespace {

void require(bool ok, const std::string& key, const std::string& what) {
  if (!ok) throw std::invalid_argument("rl.coverage." + key + ": " + what);
}

double secondsSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

detail::WalkResult runBaseline(const std::string& planner, const detail::CoverageProblem& p,
                               std::vector<int>& considered) {
  if (planner == "switching" || planner == "aco-ga") return detail::walkSwitching(p, considered);
  if (planner == "exhaustive-revisit")
    return detail::walkCoverage(p, [&p](const detail::WalkState& s, const UncertaintyTracker& t) {
      return s.last ? -1 : detail::nearestRevisit(p, t, s.cur, s.after);
    });
  return detail::walkCoverage(
      p, [](const detail::WalkState&, const UncertaintyTracker&) { return -1; });
}

}  // namespace

void CoverageConfig::validate() const {
  require(std::isfinite(c_threshold_m2) && c_threshold_m2 > 0.0, "c_threshold_m2", "must be > 0");
  require(place_max_fraction > 0.0 && place_max_fraction <= 1.0, "place_max_fraction",
          "must be in (0, 1]");
  require(aco.ants >= 1, "aco.ants", "must be >= 1");
  require(aco.iterations >= 0, "aco.iterations", "must be >= 0");
  require(aco.alpha >= 0.0 && aco.beta >= 0.0, "aco.alpha/beta", "must be >= 0");
  require(aco.rho > 0.0 && aco.rho <= 1.0, "aco.rho", "must be in (0, 1]");
  require(aco.xi >= 0.0 && aco.xi <= 1.0, "aco.xi", "must be in [0, 1]");
  require(aco.q0 >= 0.0 && aco.q0 <= 1.0, "aco.q0", "must be in [0, 1]");
  require(aco.candidates >= 1, "aco.candidates", "must be >= 1");
  require(aco.max_edges >= 1, "aco.max_edges", "must be >= 1");
  require(ga.chromosomes >= 2, "ga.chromosomes", "must be >= 2");
  require(ga.generations >= 0, "ga.generations", "must be >= 0");
  require(ga.crossover_rate >= 0.0 && ga.crossover_rate <= 1.0, "ga.crossover_rate",
          "must be in [0, 1]");
  require(ga.mutation_rate >= 0.0 && ga.mutation_rate <= 1.0, "ga.mutation_rate",
          "must be in [0, 1]");
  require(ga.elite >= 0 && ga.elite < ga.chromosomes, "ga.elite", "must be in [0, chromosomes)");
  require(ga.shift_legs >= 1, "ga.shift_legs", "must be >= 1");
  require(ga.stall_generations >= 1, "ga.stall_generations", "must be >= 1");
  require(ga.excess_penalty_m_per_m2 >= 0.0, "ga.excess_penalty_m_per_m2", "must be >= 0");
}

bool isCoveragePlanner(const std::string& planner) {
  return planner == "aco-ga" || planner == "open-loop" || planner == "exhaustive-revisit" ||
         planner == "switching";
}

PlanOutput planCoverage(const PlanGraph& pg, const TurnPaths& paths, const Config& cfg, int start,
                        std::uint64_t seed) {
  const CoverageConfig& cc = cfg.coverage;
  cc.validate();
  if (pg.m > cc.aco.max_edges)
    throw std::invalid_argument(cfg.planner + ": " + std::to_string(pg.m) +
                                " directed edges is above rl.coverage.aco.max_edges = " +
                                std::to_string(cc.aco.max_edges) + " (two m x m matrices)");
  const auto t0 = std::chrono::steady_clock::now();
  const detail::EdgeDistances dist(pg, paths, start);
  const double dist_s = secondsSince(t0);
  const detail::AntTour tour = detail::antColonyTour(dist, cc.aco, seed);
  const double aco_s = secondsSince(t0) - dist_s;
  const detail::CoverageProblem prob{pg,
                                     dist,
                                     tour.cities,
                                     start,
                                     cc.aco.closed,
                                     cfg.eif,
                                     edgeMotions(pg, cfg.eif),
                                     cc.c_threshold_m2,
                                     cc.place_max_fraction * cc.c_threshold_m2};
  std::vector<int> considered;
  detail::WalkResult walk = runBaseline(cfg.planner, prob, considered);
  std::optional<CoverageStats::Ga> ga;
  if (cfg.planner == "aco-ga") {
    const double sw_length = walk.length_m;
    const detail::GeneticResult g =
        detail::geneticRevisits(prob, considered, walk, cc.ga, seed + 1);
    walk = g.best;
    ga = CoverageStats::Ga{g.generations_run, g.evaluations, g.improved_at_generation, sw_length};
  }
  PlanOutput out;
  out.edges = walk.edges;
  out.heuristic = true;
  out.stats = CoverageStats{static_cast<long long>(walk.reached.size()),
                            static_cast<long long>(walk.revisit_after.size()),
                            walk.revisit_length_m,
                            {tour.cost_m, tour.nearest_neighbour_m, tour.improved_at_iteration,
                             static_cast<long long>(tour.cities.size())},
                            ga,
                            dist_s,
                            aco_s,
                            secondsSince(t0)};
  return out;
}

}  // namespace slamroute::rl
