// Merge-split of two parts (rl/src/fleet/MergeSplit.cpp): two parts driven as one tour and cut
// again in two, where the best split is known.
#include <gtest/gtest.h>

#include <algorithm>

#include "RlTestUtil.hpp"
#include "fleet/FleetParts.hpp"
#include "fleet/RuralPostman.hpp"

namespace slamroute::rl {
namespace {

/// The longer of the rural postman routes of parts 0 and 1 from `depot`.
double longerRoute(const PlanGraph& pg, const TurnPaths& paths, const std::vector<int>& parts,
                   int depot) {
  double longest = 0.0;
  for (int v : {0, 1}) {
    std::vector<char> required(parts.size());
    for (std::size_t e = 0; e < parts.size(); ++e) required[e] = parts[e] == v;
    longest = std::max(
        longest, fleet::routeLength(pg, fleet::ruralPostmanRoute(pg, paths, required, depot)));
  }
  return longest;
}

TEST(MergeSplit, UnevenPartsOfAStreetRowBecomeItsTwoHalves) {
  // A two-way row of four 100 m streets with the depot at its middle junction: the optimum of
  // two vehicles drives one half each, out and back, 400 m. Part 1 starts with only the last
  // street's way back, part 0 with all the rest: 800 m. Merged, the 800 m tour passes the depot
  // halfway, and cut there both routes are 400 m.
  const RoadGraph g = test::grid(1, 5);
  const PlanGraph pg = PlanGraph::build(g);
  const TurnPaths paths(pg);
  const int depot = pg.node_local[2];
  const fleet::FleetContext ctx = fleet::makeContext(g, pg, paths, {depot, depot});
  std::vector<int> parts(static_cast<std::size_t>(pg.m), 0);
  for (int e = 0; e < pg.m; ++e)
    if (pg.node_orig[static_cast<std::size_t>(pg.u[static_cast<std::size_t>(e)])] == 4)
      parts[static_cast<std::size_t>(e)] = 1;
  ASSERT_EQ(std::count(parts.begin(), parts.end(), 1), 1);
  EXPECT_NEAR(longerRoute(pg, paths, parts, depot), 800.0, 1e-6);
  const std::vector<int> split = fleet::mergeSplitParts(ctx, parts, 0, 1);
  EXPECT_NEAR(longerRoute(pg, paths, split, depot), 400.0, 1e-6);
}

TEST(MergeSplit, LeavesOtherPartsAloneAndGivesEveryMergedStreetToOneOfTheTwo) {
  GridCitySpec s;
  s.rows = 5, s.cols = 6, s.jitter_m = 20.0, s.one_way_fraction = 0.3, s.forbid_u_turns = true;
  s.seed = 4;
  const RoadGraph g = gridCity(s);
  const PlanGraph pg = PlanGraph::build(g);
  const TurnPaths paths(pg);
  const fleet::FleetContext ctx = fleet::makeContext(g, pg, paths, {0, 0, 0});
  std::vector<int> parts;
  for (int e = 0; e < pg.m; ++e) parts.push_back(e % 3);
  const std::vector<int> split = fleet::mergeSplitParts(ctx, parts, 0, 2);
  for (std::size_t e = 0; e < parts.size(); ++e) {
    if (parts[e] == 1)
      EXPECT_EQ(split[e], 1);
    else
      EXPECT_TRUE(split[e] == 0 || split[e] == 2);
  }
}

}  // namespace
}  // namespace slamroute::rl
