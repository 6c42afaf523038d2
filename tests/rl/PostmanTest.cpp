// `postman`: known lengths on small graphs, legal turns, the start node and open routes (the
// real nets: RealNetsTest.cpp).
#include <gtest/gtest.h>

#include <set>

#include "RlTestUtil.hpp"

namespace slamroute::rl {
namespace {

Config postmanCfg() {
  Config c;
  c.planner = "postman";
  return c;
}

TEST(Postman, TwoWayGridIsEveryEdgeOnce) {
  // 3x3 two-way grid, 100 m blocks: balanced, so the optimum drives each of the 24 directed
  // edges once: 12 streets * 2 directions * 100 m = 2400 m.
  const RoadGraph g = test::grid(3, 3);
  const Route r = plan(g, postmanCfg(), 1);
  EXPECT_NEAR(r.length_m, 2400.0, 1e-6);
  EXPECT_EQ(r.edges.size(), 24u);
  EXPECT_DOUBLE_EQ(r.edge_coverage_pct, 100.0);
  EXPECT_EQ(r.nodes.front(), r.nodes.back());  // closed circuit
  EXPECT_NEAR(turnFreePostmanLength(PlanGraph::build(g)), 2400.0, 1e-6);
}

TEST(Postman, UnbalancedDigraphKnownLength) {
  // 0->1, 1->2, 2->0, 0->2 (1 km each): node 2 has one extra arrival, node 0 one extra
  // departure, so 2->0 is driven twice: 5 km.
  RoadGraph g;
  for (int i = 0; i < 3; ++i) g.nodes.push_back({i, Point3(i * 1000.0, (i == 2) * 1000.0, 0), ""});
  auto add = [&](int u, int v) {
    RoadEdge e;
    e.id = static_cast<int>(g.edges.size());
    e.u = u;
    e.v = v;
    e.length_m = 1000.0;
    e.street = e.id;
    g.edges.push_back(e);
  };
  add(0, 1);
  add(1, 2);
  add(2, 0);
  add(0, 2);
  const Route r = plan(g, postmanCfg(), 1);
  EXPECT_NEAR(r.length_m, 5000.0, 1e-6);
  EXPECT_NEAR(turnFreePostmanLength(PlanGraph::build(g)), 5000.0, 1e-6);
}

TEST(Postman, NoUTurnGridStaysLegal) {
  GridCitySpec s;
  s.rows = 4;
  s.cols = 5;
  s.forbid_u_turns = true;
  s.one_way_fraction = 0.3;
  s.seed = 7;
  const Route r = plan(gridCity(s), postmanCfg(), 1);
  EXPECT_EQ(test::extra(r)["illegal_turns"].get<int>(), 0);
  EXPECT_DOUBLE_EQ(r.edge_coverage_pct, 100.0);
  EXPECT_GE(r.length_m + 1e-6, test::extra(r)["turn_free_optimum_m"].get<double>());
}

TEST(Postman, StartNodeIsRespected) {
  const RoadGraph g = test::grid(3, 4);
  Config c = postmanCfg();
  c.start_node = 5;
  const Route r = plan(g, c, 1);
  EXPECT_EQ(r.nodes.front(), 5);
  EXPECT_EQ(r.nodes.back(), 5);
}

TEST(Postman, OpenRouteStopsAfterFullCoverage) {
  GridCitySpec s;
  s.rows = 3;
  s.cols = 4;
  s.one_way_fraction = 0.4;
  s.seed = 4;
  Config closed = postmanCfg(), open = postmanCfg();
  open.postman.closed = false;
  const RoadGraph g = gridCity(s);
  const Route a = plan(g, closed, 1), b = plan(g, open, 1);
  EXPECT_LE(b.length_m, a.length_m);
  EXPECT_DOUBLE_EQ(b.edge_coverage_pct, 100.0);
  std::set<int> driven(b.edges.begin(), b.edges.end());
  EXPECT_EQ(static_cast<int>(driven.size()), test::extra(b)["plan_graph"]["edges"].get<int>());
}

}  // namespace
}  // namespace slamroute::rl

namespace slamroute::rl {
namespace {

TEST(Postman, ItsTypedStatisticsAreWhatRouteJsonCarries) {
  // Every node of the two-way grid is balanced: the legal circulation drives each edge once, at
  // the turn-free optimum (2400 m), with no detour.
  const RoadGraph g = test::grid(3, 3);
  const PlanGraph pg = PlanGraph::build(g);
  const TurnPaths paths(pg);
  const PlanOutput out = planPostman(pg, paths, postmanCfg(), 0);
  ASSERT_TRUE(std::holds_alternative<PostmanStats>(out.stats));
  const PostmanStats& s = std::get<PostmanStats>(out.stats);
  EXPECT_NEAR(s.turn_free_optimum_m, 2400.0, 1e-6);
  EXPECT_NEAR(s.legal_circulation_m, 2400.0, 1e-6);
  EXPECT_NEAR(s.detour_length_m, 0.0, 1e-9);
  EXPECT_NEAR(s.excess_over_turn_free_pct, 0.0, 1e-9);
  const nlohmann::json extra = test::extra(plan(g, postmanCfg(), 1));
  EXPECT_DOUBLE_EQ(extra.at("turn_free_optimum_m").get<double>(), s.turn_free_optimum_m);
  EXPECT_EQ(extra.at("trails_before_merge").get<long long>(), s.trails_before_merge);
  EXPECT_EQ(extra.at("forcing_rounds").get<long long>(), s.forcing_rounds);
  EXPECT_TRUE(extra.at("forcing_rounds").is_number_integer());
}

}  // namespace
}  // namespace slamroute::rl
