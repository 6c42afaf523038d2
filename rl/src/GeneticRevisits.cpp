// Genetic algorithm over revisit schedules (see GeneticRevisits.hpp): tournament selection,
// two-point crossover (rate R_cross), one mutation per mutated child (rate R_mut: move a
// revisit by up to shift_legs legs, drop one, or add one), elitism. Schedules already seen are
// not walked again.
#include "GeneticRevisits.hpp"

#include <algorithm>
#include <random>
#include <string>
#include <unordered_map>

#include "Index.hpp"

namespace slamroute::rl::detail {

namespace {

using Chromosome = std::string;  // one char (0/1) per revisit position

struct Individual {
  Chromosome genes;
  bool feasible = true;
  double score = 0.0;  ///< length, plus the excess penalty when the bound breaks [m]
  bool better(const Individual& o) const {
    return std::make_pair(!feasible, score) < std::make_pair(!o.feasible, o.score);
  }
  bool operator<(const Individual& o) const {
    if (better(o) || o.better(*this)) return better(o);
    return genes < o.genes;
  }
};

class Population {
 public:
  Population(const CoverageProblem& p, const std::vector<int>& targets, double penalty)
      : p_(p), targets_(targets), penalty_(penalty) {
    pos_of_.assign(targets.size(), -1);
    for (std::size_t j = 0; j < targets.size(); ++j)
      if (targets[j] >= 0) {
        pos_of_[j] = static_cast<int>(active_.size());
        active_.push_back(static_cast<int>(j));
      }
  }
  int size() const { return static_cast<int>(active_.size()); }
  Chromosome fromRevisits(const std::vector<int>& after) const {
    Chromosome c(sz(size()), 0);
    for (int j : after)
      if (pos_of_[sz(j)] >= 0) c[sz(pos_of_[sz(j)])] = 1;
    return c;
  }
  WalkResult walk(const Chromosome& c) const {
    return walkCoverage(p_, [&](const WalkState& s, const UncertaintyTracker&) {
      const int pos = pos_of_[sz(s.j)];
      return pos >= 0 && c[sz(pos)] ? targets_[sz(s.j)] : -1;
    });
  }
  Individual evaluate(const Chromosome& c) {
    auto it = cache_.find(c);
    if (it == cache_.end()) {
      const WalkResult w = walk(c);
      it = cache_.emplace(c, std::make_pair(w.excess_m2, w.length_m)).first;
      ++evaluations;
    }
    const auto [excess, length] = it->second;
    return {c, excess <= 0.0, length + penalty_ * excess};
  }
  int evaluations = 0;

 private:
  const CoverageProblem& p_;
  const std::vector<int>& targets_;
  double penalty_;
  std::vector<int> pos_of_, active_;
  std::unordered_map<Chromosome, std::pair<double, double>> cache_;
};

void mutate(Chromosome& c, int shift, std::mt19937_64& rng) {
  const int n = static_cast<int>(c.size());
  if (n == 0) return;
  std::vector<int> set;
  for (int i = 0; i < n; ++i)
    if (c[sz(i)]) set.push_back(i);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  const double r = uni(rng);
  if (set.empty() || r >= 0.75) {
    c[sz(std::uniform_int_distribution<int>(0, n - 1)(rng))] = 1;
    return;
  }
  const int i =
      set[sz(std::uniform_int_distribution<int>(0, static_cast<int>(set.size()) - 1)(rng))];
  c[sz(i)] = 0;
  if (r >= 0.5) return;  // drop
  int d = std::uniform_int_distribution<int>(1, std::max(1, shift))(rng);
  if (uni(rng) < 0.5) d = -d;
  c[sz(std::clamp(i + d, 0, n - 1))] = 1;
}

Chromosome crossover(const Chromosome& a, const Chromosome& b, std::mt19937_64& rng) {
  const int n = static_cast<int>(a.size());
  if (n < 2) return a;
  int x = std::uniform_int_distribution<int>(0, n - 1)(rng);
  int y = std::uniform_int_distribution<int>(0, n - 1)(rng);
  if (x > y) std::swap(x, y);
  Chromosome c = a;
  std::copy(b.begin() + x, b.begin() + y + 1, c.begin() + x);
  return c;
}

const Individual& tournament(const std::vector<Individual>& pop, std::mt19937_64& rng) {
  std::uniform_int_distribution<int> pick(0, static_cast<int>(pop.size()) - 1);
  const Individual& a = pop[sz(pick(rng))];
  const Individual& b = pop[sz(pick(rng))];
  return b < a ? b : a;
}

}  // namespace

GeneticResult geneticRevisits(const CoverageProblem& p, const std::vector<int>& targets,
                              const WalkResult& switching, const GeneticConfig& cfg,
                              std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  Population popu(p, targets, cfg.excess_penalty_m_per_m2);
  std::vector<Individual> pop;
  const Chromosome sw = popu.fromRevisits(switching.revisit_after);
  pop.push_back(popu.evaluate(sw));
  pop.push_back(popu.evaluate(Chromosome(sz(popu.size()), 1)));
  while (static_cast<int>(pop.size()) < cfg.chromosomes) {
    Chromosome c = sw;
    mutate(c, cfg.shift_legs, rng);
    pop.push_back(popu.evaluate(c));
  }
  std::sort(pop.begin(), pop.end());
  GeneticResult res;
  res.seed_length_m = switching.length_m;
  for (int g = 1; g <= cfg.generations; ++g) {
    std::vector<Individual> next(
        pop.begin(), pop.begin() + std::min<int>(cfg.elite, static_cast<int>(pop.size())));
    while (static_cast<int>(next.size()) < cfg.chromosomes) {
      const Individual& a = tournament(pop, rng);
      const Individual& b = tournament(pop, rng);
      Chromosome c = uni(rng) < cfg.crossover_rate ? crossover(a.genes, b.genes, rng) : a.genes;
      if (uni(rng) < cfg.mutation_rate) mutate(c, cfg.shift_legs, rng);
      next.push_back(popu.evaluate(c));
    }
    std::sort(next.begin(), next.end());
    if (next.front().better(pop.front())) res.improved_at_generation = g;
    pop = std::move(next);
    res.generations_run = g;
    if (g - res.improved_at_generation >= cfg.stall_generations) break;
  }
  res.best = popu.walk(pop.front().genes);
  res.evaluations = popu.evaluations;
  return res;
}

}  // namespace slamroute::rl::detail
