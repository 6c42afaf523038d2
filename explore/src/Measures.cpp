// Milestones of the coverage curve and the offline postman bound.
#include "slamroute/explore/Measures.hpp"

#include <cmath>

#include "slamroute/rl/Config.hpp"
#include "slamroute/rl/Planners.hpp"

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

double offlineBoundLength(const rl::PlanGraph& pg, int start_edge) {
  const rl::TurnPaths paths(pg);
  const rl::Config cfg;
  const rl::PlanOutput out = rl::planPostman(pg, paths, cfg, pg.u[static_cast<std::size_t>(start_edge)]);
  double len = 0.0;
  for (int e : out.edges) len += pg.len[static_cast<std::size_t>(e)];
  return len;
}

}  // namespace slamroute::explore
