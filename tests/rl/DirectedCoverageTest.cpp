// Coverage figures that mean what they say: the two-way figure on the graph against the directed
// coverage of the net's SUMO edges (core/SumoCoverage.hpp), on routes the planners make.
#include <gtest/gtest.h>

#include "RlTestUtil.hpp"
#include "TwoWayStreetNet.hpp"
#include "slamroute/core/SumoCoverage.hpp"

namespace slamroute::rl {
namespace {

TEST(DirectedCoverage, TwoWayStreetDrivenOneWayIsHalfDirectedAndWholeTwoWay) {
  const SumoNet net = slamroute::test::twoWayStreetNet();  // and a bus lane
  const RoadGraph g = RoadGraph::fromSumoNet(net, /*lscc_only=*/false);
  const PlanGraph pg = PlanGraph::build(g);
  int ab = -1;
  for (int e = 0; e < pg.m; ++e)
    if (g.edges[static_cast<std::size_t>(pg.edge_orig[static_cast<std::size_t>(e)])].sumo_edges ==
        std::vector<std::string>{"AB"})
      ab = e;
  ASSERT_GE(ab, 0);
  Route r;
  fillRouteMetrics(pg, g, pg.u[static_cast<std::size_t>(ab)], {ab}, EifConfig{}, r);
  EXPECT_DOUBLE_EQ(r.edge_coverage_pct, 100.0);  // the street counted once
  const SumoCoverage c = sumoCoverage(net, r.sumo_edges);
  EXPECT_DOUBLE_EQ(c.edges_pct, 50.0);
  EXPECT_DOUBLE_EQ(c.length_pct, 50.0);
}

TEST(DirectedCoverage, PostmanOnAClosedGridDrivesEveryDirectedEdge) {
  const SumoNet net =
      SumoNet::read(std::filesystem::path(SLAMROUTE_SOURCE_DIR) / "networks/test/grid3x3.net.xml");
  Config cfg;
  cfg.planner = "postman";
  const Route r = plan(RoadGraph::fromSumoNet(net, /*lscc_only=*/false), cfg, 1);
  const SumoCoverage c = sumoCoverage(net, r.sumo_edges);
  EXPECT_EQ(c.edges_total, 24);  // 12 two-way streets
  EXPECT_EQ(c.edges_driven, 24);
  EXPECT_DOUBLE_EQ(c.edges_pct, 100.0);
  EXPECT_DOUBLE_EQ(c.length_pct, 100.0);
  EXPECT_EQ(c.turns_without_connection, 0);  // every turn is one SUMO allows
  EXPECT_GT(c.route_in_junctions_m, 0.0);    // and each passes the junction's internal lanes
}

}  // namespace
}  // namespace slamroute::rl
