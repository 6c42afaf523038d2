// The simple strategies (nearest, gp-frontier, siba) and the strategy factory.
#include "slamroute/explore/Strategies.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>

#include "FleetStrategy.hpp"
#include "slamroute/explore/GpFrontier.hpp"
#include "slamroute/explore/KnownPaths.hpp"

namespace slamroute::explore {

bool FleetView::open(int edge, int k) const {
  if (!streets.known(edge) || driven[static_cast<std::size_t>(edge)]) return false;
  for (std::size_t j = 0; j < targets.size(); ++j)
    if (static_cast<int>(j) != k && targets[j] == edge) return false;
  return true;
}

Decision nearestOpen(const FleetView& f, int k) {
  const KnownPaths paths(f.pg, f.vehicles[static_cast<std::size_t>(k)].edge,
                         [&](int e) { return f.streets.known(e); });
  const auto t = paths.nearest([&](int e) { return f.open(e, k); });
  if (!t) return {};
  return {paths.pathTo(*t)->edges, *t};
}

namespace {

class NearestStrategy : public Strategy {
 public:
  Decision decide(const FleetView& f, int k) override { return nearestOpen(f, k); }
};

/// Open streets scored by (max frontier probability on them + floor) * exp(-d / scale).
class GpFrontierStrategy : public Strategy {
 public:
  explicit GpFrontierStrategy(const GpConfig& cfg) : cfg_(cfg) {}
  Decision decide(const FleetView& f, int k) override {
    const GpFrontierMap gp(f.grid, cfg_);
    std::map<int, double> p_edge;
    for (const FrontierPoint& fp : f.streets.frontierPoints()) {
      if (!f.open(fp.edge, k)) continue;
      double& p = p_edge[fp.edge];
      p = std::max(p, gp.frontierProbability(fp.cell));
    }
    const KnownPaths paths(f.pg, f.vehicles[static_cast<std::size_t>(k)].edge,
                           [&](int e) { return f.streets.known(e); });
    int best = -1;
    double best_score = -1.0;
    for (int e = 0; e < f.pg.m; ++e) {
      const double d = paths.distance(e);
      if (!f.open(e, k) || !std::isfinite(d)) continue;
      const auto it = p_edge.find(e);
      const double p = (it == p_edge.end() ? 0.0 : it->second) + kFloor;
      const double score = p * std::exp(-d / cfg_.distance_scale_m);
      if (score > best_score) {
        best_score = score;
        best = e;
      }
    }
    if (best < 0) return {};
    return {paths.pathTo(best)->edges, best};
  }

 private:
  static constexpr double kFloor = 0.05;  ///< streets without frontier still get covered
  GpConfig cfg_;
};

/// Signed turn from edge a onto edge b [rad], left positive, in (-pi, pi].
double turnAngle(const rl::PlanGraph& pg, int a, int b) {
  return std::remainder(
      pg.heading[static_cast<std::size_t>(b)] - pg.heading[static_cast<std::size_t>(a)],
      2.0 * std::numbers::pi);
}

class SibaStrategy : public Strategy {
 public:
  Decision decide(const FleetView& f, int k) override {
    const int e = f.vehicles[static_cast<std::size_t>(k)].edge;
    std::vector<std::pair<double, int>> turns;  // rightmost first, a U-turn last
    for (int i = f.pg.nextBegin(e); i < f.pg.nextEnd(e); ++i) {
      const int n = f.pg.next[static_cast<std::size_t>(i)];
      const bool u_turn =
          f.pg.v[static_cast<std::size_t>(n)] == f.pg.u[static_cast<std::size_t>(e)];
      turns.push_back({u_turn ? 10.0 : turnAngle(f.pg, e, n), n});
    }
    std::sort(turns.begin(), turns.end());
    for (const auto& [angle, n] : turns)
      if (f.open(n, k)) return {{n}, n};
    return nearestOpen(f, k);
  }
};

}  // namespace

const std::vector<std::string>& strategyNames() {
  static const std::vector<std::string> names = {"nearest", "gp-frontier", "fleet", "central",
                                                 "siba"};
  return names;
}

std::unique_ptr<Strategy> makeStrategy(const std::string& name, const Config& cfg,
                                       std::uint64_t seed) {
  if (name == "nearest") return std::make_unique<NearestStrategy>();
  if (name == "gp-frontier") return std::make_unique<GpFrontierStrategy>(cfg.gp);
  if (name == "fleet") return makeFleetStrategy(cfg.fleet, cfg.fleet.group_size, seed);
  if (name == "central") return makeFleetStrategy(cfg.fleet, 1, seed);
  if (name == "siba") return std::make_unique<SibaStrategy>();
  std::string all;
  for (const auto& n : strategyNames()) all += (all.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown strategy '" + name + "' (one of " + all + ")");
}

}  // namespace slamroute::explore
