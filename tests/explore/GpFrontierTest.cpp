// GP frontier probability on a synthetic map with a known frontier: ground on the left, unknown
// on the right, a wall along the top of the ground part.
#include <gtest/gtest.h>

#include <cmath>

#include "slamroute/explore/GpFrontier.hpp"

namespace slamroute::explore {
namespace {

/// 60 x 40 cells: columns 0..29 ground, 30.. unknown; row 39 obstacle over columns 0..29.
OccupancyGrid syntheticMap() {
  OccupancyGrid grid({0, 0}, {60, 40}, 1.0);
  for (int r = 0; r < 40; ++r)
    for (int c = 0; c < 30; ++c) grid.mark(r * 60 + c, r == 39 ? Cell::Obstacle : Cell::Ground);
  return grid;
}

TEST(GpFrontier, LocalKernelIsTheMaternKernelOverCellOffsets) {
  const OccupancyGrid grid = syntheticMap();
  GpConfig cfg;
  const GpFrontierMap gp(grid, cfg);
  ASSERT_EQ(gp.kernel().size(), 121u);
  EXPECT_NEAR(gp.kernel()[60], cfg.signal_var, 1e-12);             // centre: r = 0
  const double a = std::sqrt(3.0) * 5.0 / cfg.length_scale_cells;  // (5, 0) cells off centre
  EXPECT_NEAR(gp.kernel()[55], cfg.signal_var * (1 + a) * std::exp(-a), 1e-12);
}

TEST(GpFrontier, ProbabilityPeaksAtTheKnownFrontierAwayFromObstacles) {
  const OccupancyGrid grid = syntheticMap();
  const GpFrontierMap gp(grid, GpConfig{});
  // along row 15 (far from the wall) the peak lies on the frontier: column 29 or 30
  int best = -1;
  double best_p = -1;
  for (int c = 0; c < 60; ++c) {
    const double p = gp.frontierProbability(15 * 60 + c);
    if (p > best_p) {
      best_p = p;
      best = c;
    }
  }
  EXPECT_GT(best_p, 0.0);
  EXPECT_GE(best, 28);
  EXPECT_LE(best, 31);
  // deep in the free part and deep in the unknown part there is no frontier
  EXPECT_NEAR(gp.frontierProbability(15 * 60 + 10), 0.0, 1e-9);
  EXPECT_NEAR(gp.frontierProbability(15 * 60 + 50), 0.0, 1e-9);
  // the same frontier next to the wall is less likely one (beta term)
  EXPECT_LT(gp.frontierProbability(37 * 60 + best), best_p);
  // GP occupancy: free cells low, the wall high, unknown in between
  EXPECT_LT(gp.at(10, 15).p_gp, gp.at(50, 15).p_gp);
  EXPECT_GT(gp.at(10, 39).p_obs, gp.at(10, 15).p_obs);
}

}  // namespace
}  // namespace slamroute::explore
