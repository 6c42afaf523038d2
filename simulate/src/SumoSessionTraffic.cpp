// BackgroundTraffic: random trips generated in C++ from the seed, kept at a steady density.
// Choice: random trips as SUMO's randomTrips.py makes them, but instead of calling it (Python, a
// second process, files) we draw origin/destination edges ourselves and let SUMO's router find
// the route (Simulation::findRoute), which is what randomTrips + duarouter would do.
#include <libsumo/libsumo.h>

#include <algorithm>
#include <cmath>

#include "slamroute/core/DriveGraph.hpp"
#include "slamroute/core/SumoNet.hpp"
#include "slamroute/simulate/SumoSession.hpp"

namespace slamroute::simulate {

BackgroundTraffic::BackgroundTraffic(const SumoSession& session, const SumoNet& net,
                                     double vehicles_per_km, std::uint64_t seed, std::string prefix)
    : session_(session), rng_(seed ^ 0x9e3779b97f4a7c15ULL), prefix_(std::move(prefix)) {
  const DriveGraph dg = DriveGraph::fromNet(net);
  double km = 0.0;
  for (std::size_t i = 0; i < dg.edges.size(); ++i) {
    km += dg.edges[i].length_m / 1000.0;
    // Long enough for a car to be inserted at a random free position.
    if (dg.in_lscc_edge[i] && dg.edges[i].length_m > 15.0) edges_.push_back(dg.edges[i].sumo_edge);
  }
  target_ =
      edges_.size() < 2 ? 0 : static_cast<int>(std::lround(std::max(0.0, vehicles_per_km) * km));
}

void BackgroundTraffic::update() {
  if (target_ <= 0) return;
  session_.guard("background traffic", [&] {
    int live = 0;
    for (const auto& id : libsumo::Vehicle::getIDList()) live += owns(id) ? 1 : 0;
    for (const auto& id : libsumo::Simulation::getPendingVehicles()) live += owns(id) ? 1 : 0;
    std::uniform_int_distribution<std::size_t> pick(0, edges_.size() - 1);
    // At most a few insertions per step so that traffic does not appear in one burst later on.
    const int max_new = spawned_ == 0 ? target_ : 3;
    for (int n = 0; live < target_ && n < max_new; ++n) {
      std::vector<std::string> route;
      for (int attempt = 0; attempt < 10 && route.empty(); ++attempt) {
        const std::string& from = edges_[pick(rng_)];
        const std::string& to = edges_[pick(rng_)];
        if (from == to) continue;
        route = libsumo::Simulation::findRoute(from, to, "DEFAULT_VEHTYPE").edges;
      }
      if (route.empty()) return;
      const std::string id = prefix_ + std::to_string(spawned_++);
      libsumo::Route::add(id + "_route", route);
      libsumo::Vehicle::add(id, id + "_route", "DEFAULT_VEHTYPE", "now", "best", "random_free",
                            "max");
      ++live;
    }
  });
}

}  // namespace slamroute::simulate
