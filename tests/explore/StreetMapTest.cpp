// Frontiers found where a street leaves the known part of the 3 x 3 grid net.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "slamroute/core/RoadGraph.hpp"
#include "slamroute/core/SumoNet.hpp"
#include "slamroute/explore/KnownPaths.hpp"
#include "slamroute/explore/StreetMap.hpp"

namespace slamroute::explore {
namespace {

struct GridNet {
  SumoNet net = SumoNet::read(std::string(SLAMROUTE_SOURCE_DIR) + "/networks/test/grid3x3.net.xml");
  RoadGraph g = RoadGraph::fromSumoNet(net);
  rl::PlanGraph pg = rl::PlanGraph::build(g);
  std::string sumo(int e) const {
    return g.edges[static_cast<std::size_t>(pg.edge_orig[static_cast<std::size_t>(e)])]
        .sumo_edges.front();
  }
};

/// Marks every cell within `radius` of `centre` as ground (what a vehicle standing there sees).
std::vector<int> seeDisc(OccupancyGrid& grid, const Point2& centre, double radius) {
  std::vector<int> changed;
  for (int i = 0; i < static_cast<int>(grid.size()); ++i)
    if ((grid.centre(i) - centre).norm() <= radius && grid.mark(i, Cell::Ground))
      changed.push_back(i);
  grid.updateFrontiers(changed);
  return changed;
}

TEST(StreetMap, FrontierStreetsAreTheOnesLeavingTheKnownDisc) {
  const GridNet n;
  OccupancyGrid grid({0, 0}, {600, 600}, 2.0);
  StreetMap streets(n.pg, n.g, grid);
  EXPECT_EQ(streets.numKnown(), 0);
  // junction g00 is at (100, 100); 150 m around it covers part of its two streets only
  streets.update(seeDisc(grid, {100, 100}, 150));
  std::set<std::string> frontier, known;
  for (const FrontierPoint& f : streets.frontierPoints()) frontier.insert(n.sumo(f.edge));
  for (int e = 0; e < n.pg.m; ++e)
    if (streets.known(e)) known.insert(n.sumo(e));
  const std::set<std::string> leaving = {"g00_g01", "g01_g00", "g00_g10", "g10_g00"};
  EXPECT_EQ(frontier, leaving);
  EXPECT_EQ(known, leaving);
  for (int e = 0; e < n.pg.m; ++e) EXPECT_FALSE(streets.fullySeen(e)) << n.sumo(e);
  // the frontier points lie on the disc's rim, 150 m from g00
  for (const FrontierPoint& f : streets.frontierPoints())
    EXPECT_NEAR((f.pos - Point2(100, 100)).norm(), 150.0, 3.0);
  // seeing all of it closes every frontier and every street is fully seen
  streets.update(seeDisc(grid, {300, 300}, 400));
  EXPECT_TRUE(streets.frontierPoints().empty());
  EXPECT_EQ(streets.numKnown(), n.pg.m);
  for (int e = 0; e < n.pg.m; ++e) EXPECT_TRUE(streets.fullySeen(e)) << n.sumo(e);
}

TEST(KnownPaths, PlanOnlyOverKnownStreets) {
  const GridNet n;
  int e11_01 = -1, e01_02 = -1, e10_11 = -1;
  for (int e = 0; e < n.pg.m; ++e) {
    if (n.sumo(e) == "g11_g01") e11_01 = e;
    if (n.sumo(e) == "g01_g02") e01_02 = e;
    if (n.sumo(e) == "g10_g11") e10_11 = e;
  }
  ASSERT_GE(e11_01, 0);
  // from g10_g11 (arriving at the centre g11) left to g01, then right to g02: 2 edges
  const KnownPaths all(n.pg, e10_11, [](int) { return true; });
  const auto p = all.pathTo(e01_02);
  ASSERT_TRUE(p);
  EXPECT_EQ(p->edges, (std::vector<int>{e11_01, e01_02}));
  EXPECT_NEAR(
      p->length_m,
      n.pg.len[static_cast<std::size_t>(e11_01)] + n.pg.len[static_cast<std::size_t>(e01_02)],
      1e-9);
  // without g11_g01 known the way round is longer (at least 4 edges)
  const KnownPaths partial(n.pg, e10_11, [&](int e) { return e != e11_01; });
  ASSERT_TRUE(partial.pathTo(e01_02));
  EXPECT_GE(partial.pathTo(e01_02)->edges.size(), 4u);
  EXPECT_GT(partial.distance(e01_02), all.distance(e01_02));
  // nothing known: nothing reachable
  const KnownPaths none(n.pg, e10_11, [](int) { return false; });
  EXPECT_FALSE(none.pathTo(e01_02));
  EXPECT_FALSE(none.nearest([](int) { return true; }));
}

}  // namespace
}  // namespace slamroute::explore
