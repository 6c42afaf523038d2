// plan(): bad input and graph preparation (largest legally drivable part).
#include <gtest/gtest.h>
#include "TestTmp.hpp"

#include <algorithm>

#include "RlTestUtil.hpp"

namespace slamroute::rl {
namespace {

template <class F>
std::string errorOf(F f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

TEST(Plan, EmptyGraphIsAnError) {
  RoadGraph g;
  Config c;
  const std::string msg = errorOf([&] { plan(g, c, 1, "empty.json"); });
  EXPECT_NE(msg.find("empty.json"), std::string::npos) << msg;
  EXPECT_NE(msg.find("empty"), std::string::npos) << msg;
}

TEST(Plan, UnknownPlannerIsAnError) {
  Config c;
  c.planner = "dijkstra";
  const std::string msg = errorOf([&] { plan(test::grid(2, 2), c, 1); });
  EXPECT_NE(msg.find("unknown planner 'dijkstra'"), std::string::npos) << msg;
}

RoadGraph twoIslands() {
  // A 3x3 grid (ids 0..8) plus a separate 2-node two-way street (ids 9, 10).
  RoadGraph g = test::grid(3, 3);
  for (int i = 0; i < 2; ++i) g.nodes.push_back({9 + i, Point3(1000.0 + 100 * i, 0, 0), ""});
  for (auto [u, v] : {std::pair{9, 10}, std::pair{10, 9}}) {
    RoadEdge e;
    e.id = static_cast<int>(g.edges.size());
    e.u = u;
    e.v = v;
    e.length_m = 100.0;
    e.street = 1000;
    g.edges.push_back(e);
  }
  return g;
}

TEST(Plan, DisconnectedGraphPlansOnLargestPart) {
  Config c;
  c.planner = "postman";
  const Route r = plan(twoIslands(), c, 1);
  const auto x = test::extra(r);
  EXPECT_EQ(x["plan_graph"]["nodes"].get<int>(), 9);
  EXPECT_EQ(x["plan_graph"]["dropped_nodes"].get<int>(), 2);
  EXPECT_DOUBLE_EQ(r.node_coverage_pct, 100.0);
}

TEST(Plan, UnreachableStartIsAnError) {
  Config c;
  c.planner = "postman";
  c.start_node = 10;
  const std::string msg = errorOf([&] { plan(twoIslands(), c, 1); });
  EXPECT_NE(msg.find("start node 10 is unreachable"), std::string::npos) << msg;
  c.start_node = 99;
  EXPECT_NE(errorOf([&] { plan(twoIslands(), c, 1); }).find("does not exist"), std::string::npos);
}

TEST(Plan, UTurnOnlyDeadEndWithoutTurnIsDropped) {
  // A one-way stub leading into a node with no allowed exit cannot be part of a route.
  RoadGraph g = test::grid(2, 2);
  g.nodes.push_back({4, Point3(-100, 0, 0), ""});
  RoadEdge e;
  e.id = static_cast<int>(g.edges.size());
  e.u = 0;
  e.v = 4;
  e.length_m = 100.0;
  g.edges.push_back(e);
  g.validate("test");
  const PlanGraph pg = PlanGraph::build(g);
  EXPECT_EQ(pg.dropped_edges, 1);
  EXPECT_EQ(pg.n, 4);
}

TEST(Plan, RouteJsonRoundTrip) {
  Config c;
  c.planner = "postman";
  const Route r = plan(test::grid(2, 3), c, 7);
  const auto path = slamroute::test::testTmp() / "rl_plan_roundtrip.json";
  std::filesystem::create_directories(path.parent_path());
  r.writeJson(path);
  const Route back = Route::readJson(path);
  EXPECT_EQ(back.planner, "postman");
  EXPECT_EQ(back.seed, 7u);
  EXPECT_EQ(back.edges, r.edges);
  EXPECT_NEAR(back.length_m, r.length_m, 1e-6);
}

TEST(Plan, RandomWalkStopsAtItsLengthBudget) {
  Config c;
  c.planner = "random";
  const RoadGraph g = test::grid(4, 4);  // 100 m blocks
  const Route free_walk = plan(g, c, 3);
  EXPECT_DOUBLE_EQ(free_walk.node_coverage_pct, 100.0);
  c.random.budget_m = 450.0;
  const Route budgeted = plan(g, c, 3);
  // Stops on the first edge that reaches the budget: at least 450 m, less than one block more.
  EXPECT_GE(budgeted.length_m, 450.0);
  EXPECT_LT(budgeted.length_m, 450.0 + 100.0 + 1e-6);
  EXPECT_LT(budgeted.node_coverage_pct, 100.0);
  // Same seed, same prefix: the budgeted walk is the start of the free walk.
  ASSERT_LE(budgeted.edges.size(), free_walk.edges.size());
  EXPECT_TRUE(std::equal(budgeted.edges.begin(), budgeted.edges.end(), free_walk.edges.begin()));
}

}  // namespace
}  // namespace slamroute::rl
