// Milestones of the coverage curve and the offline fleet bound.
#include "slamroute/explore/Measures.hpp"

#include <algorithm>
#include <cmath>

#include "slamroute/rl/Config.hpp"
#include "slamroute/rl/Fleet.hpp"

namespace slamroute::explore {

Milestone milestoneAt(const std::vector<CoverageSample>& curve, int total_edges, double share) {
  Milestone m;
  m.share = share;
  const double need = std::ceil(share * total_edges - 1e-9);
  for (const CoverageSample& c : curve) {
    if (c.edges_driven < need) continue;
    m.reached = true;
    m.time_s = c.time_s;
    m.fleet_distance_m = c.fleet_distance_m;
    m.vehicle_distance_m = c.vehicle_distance_m;
    break;
  }
  return m;
}

OfflineBound offlineFleetBound(const RoadGraph& g, const rl::PlanGraph& pg,
                               const std::vector<int>& start_edges, std::uint64_t seed) {
  // more vehicles than streets: the extra ones would have nothing to drive in the plan
  const std::size_t k = std::min(start_edges.size(), static_cast<std::size_t>(pg.num_streets));
  rl::Config cfg;
  cfg.fleet.vehicles = static_cast<int>(k);
  cfg.fleet.strategy = "partition";
  std::vector<int> depots;
  for (int e : std::vector<int>(start_edges.begin(), start_edges.begin() + static_cast<long>(k)))
    depots.push_back(pg.node_orig[static_cast<std::size_t>(pg.u[static_cast<std::size_t>(e)])]);
  const FleetRoute plan = rl::planFleet(g, cfg, depots, seed, "explore offline bound");
  return {plan.total_length_m, plan.makespan_m};
}

}  // namespace slamroute::explore
