// Ant Colony System over directed streets (see AntColony.hpp).
//  - State transition: from city r, with probability q0 take the unvisited candidate s with the
//    largest tau(r,s)^alpha * eta(r,s)^beta (eta = 1 / legal distance), otherwise draw s with
//    probability proportional to it. When every candidate is visited: the nearest unvisited city.
//  - Local update after each step: tau = (1 - xi) tau + xi tau0.
//  - Global update after each iteration, on the best tour so far: tau = (1 - rho) tau + rho / L.
// Pheromone lives on the candidate arcs only (m x candidates); tau0 = 1 / (m * L_nn).
#include "AntColony.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>

#include "Index.hpp"

namespace slamroute::rl::detail {

namespace {

/// Row r of the candidate lists: row m is the start node, rows 0..m-1 the cities.
struct Candidates {
  int k = 0;
  std::vector<int> city;     ///< (m + 1) x k, -1 padded
  std::vector<double> heur;  ///< eta^beta per candidate arc
  std::vector<double> tau;   ///< pheromone per candidate arc
  std::size_t at(int r) const { return sz(r) * sz(k); }
};

Candidates buildCandidates(const EdgeDistances& d, const AntColonyConfig& cfg) {
  const int m = d.edges();
  Candidates c;
  c.k = std::min(cfg.candidates, m);
  c.city.assign(sz(m + 1) * sz(c.k), -1);
  c.heur.assign(c.city.size(), 0.0);
  std::vector<int> order(sz(m));
  for (int r = 0; r <= m; ++r) {
    const int from = r < m ? r : -1;
    std::iota(order.begin(), order.end(), 0);
    auto closer = [&](int a, int b) {
      return d.d(from, a) < d.d(from, b) || (d.d(from, a) == d.d(from, b) && a < b);
    };
    std::partial_sort(order.begin(), order.begin() + c.k, order.end(), closer);
    int n = 0;
    for (int i = 0; i < c.k; ++i) {
      const int s = order[sz(i)];
      if (s == from || !std::isfinite(d.d(from, s))) continue;
      c.city[c.at(r) + sz(n)] = s;
      c.heur[c.at(r) + sz(n)] = std::pow(1.0 / std::max(1e-3f, d.d(from, s)), cfg.beta);
      ++n;
    }
  }
  return c;
}

class Ant {
 public:
  Ant(const EdgeDistances& d, const AntColonyConfig& cfg) : d_(d), cfg_(cfg), m_(d.edges()) {}

  /// One tour; greedy = nearest neighbour (q0 = 1, no pheromone, no local update).
  std::vector<int> build(Candidates& c, double tau0, std::mt19937_64& rng, bool greedy,
                         double& cost) {
    visited_.assign(sz(m_), 0);
    unvisited_.resize(sz(m_));
    std::iota(unvisited_.begin(), unvisited_.end(), 0);
    where_ = unvisited_;
    std::vector<int> tour;
    tour.reserve(sz(m_));
    cost = 0.0;
    int r = m_;  // the start node row
    for (int step = 0; step < m_; ++step) {
      int slot = -1;
      const int s = greedy ? nearestUnvisited(r) : choose(c, r, rng, slot);
      if (slot >= 0) {
        double& t = c.tau[c.at(r) + sz(slot)];
        t = (1.0 - cfg_.xi) * t + cfg_.xi * tau0;
      }
      cost += d_.d(r < m_ ? r : -1, s);
      visit(s);
      tour.push_back(s);
      r = s;
    }
    if (cfg_.closed && !tour.empty()) {
      const int f = d_.returnEdge(tour.back());
      if (f >= 0) cost += d_.d(tour.back(), f);
    }
    return tour;
  }

 private:
  int choose(const Candidates& c, int r, std::mt19937_64& rng, int& slot) {
    std::uniform_real_distribution<double> uni(0.0, 1.0);
    const bool exploit = uni(rng) < cfg_.q0;
    double best = -1.0, total = 0.0;
    scores_.clear();
    for (int i = 0; i < c.k; ++i) {
      const int s = c.city[c.at(r) + sz(i)];
      const double sc = s >= 0 && !visited_[sz(s)]
                            ? std::pow(c.tau[c.at(r) + sz(i)], cfg_.alpha) * c.heur[c.at(r) + sz(i)]
                            : 0.0;
      scores_.push_back(sc);
      total += sc;
      if (sc > best) best = sc, slot = sc > 0.0 ? i : -1;
    }
    if (total <= 0.0) {
      slot = -1;
      return nearestUnvisited(r);
    }
    if (!exploit) {
      double x = uni(rng) * total;
      for (int i = 0; i < c.k; ++i) {
        if (scores_[sz(i)] <= 0.0) continue;
        slot = i;
        x -= scores_[sz(i)];
        if (x <= 0.0) break;
      }
    }
    return c.city[c.at(r) + sz(slot)];
  }

  int nearestUnvisited(int r) const {
    const int from = r < m_ ? r : -1;
    int best = -1;
    float best_d = std::numeric_limits<float>::infinity();
    for (int s : unvisited_)
      if (d_.d(from, s) < best_d || (d_.d(from, s) == best_d && s < best))
        best_d = d_.d(from, s), best = s;
    return best >= 0 ? best : unvisited_.front();
  }

  void visit(int s) {
    visited_[sz(s)] = 1;
    const int i = where_[sz(s)];
    const int last = unvisited_.back();
    unvisited_[sz(i)] = last;
    where_[sz(last)] = i;
    unvisited_.pop_back();
  }

  const EdgeDistances& d_;
  const AntColonyConfig& cfg_;
  int m_;
  std::vector<char> visited_;
  std::vector<int> unvisited_, where_;
  std::vector<double> scores_;
};

void globalUpdate(Candidates& c, const std::vector<int>& tour, double length, double rho, int m) {
  int r = m;
  for (int s : tour) {
    for (int i = 0; i < c.k; ++i)
      if (c.city[c.at(r) + sz(i)] == s) {
        double& t = c.tau[c.at(r) + sz(i)];
        t = (1.0 - rho) * t + rho / length;
      }
    r = s;
  }
}

}  // namespace

AntTour antColonyTour(const EdgeDistances& d, const AntColonyConfig& cfg, std::uint64_t seed) {
  const int m = d.edges();
  std::mt19937_64 rng(seed);
  Candidates c = buildCandidates(d, cfg);
  Ant ant(d, cfg);
  AntTour best;
  best.cities = ant.build(c, 0.0, rng, /*greedy=*/true, best.cost_m);
  best.nearest_neighbour_m = best.cost_m;
  const double tau0 = 1.0 / (m * std::max(best.cost_m, 1e-6));
  c.tau.assign(c.city.size(), tau0);
  for (int it = 1; it <= cfg.iterations; ++it) {
    for (int a = 0; a < cfg.ants; ++a) {
      double cost = 0.0;
      std::vector<int> tour = ant.build(c, tau0, rng, /*greedy=*/false, cost);
      if (cost < best.cost_m - 1e-6) {
        best.cities = std::move(tour);
        best.cost_m = cost;
        best.improved_at_iteration = it;
      }
    }
    globalUpdate(c, best.cities, best.cost_m, cfg.rho, m);
  }
  return best;
}

}  // namespace slamroute::rl::detail
