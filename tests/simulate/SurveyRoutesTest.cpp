// coveringRoutes: known answers on the shipped test nets (no SUMO).
#include <gtest/gtest.h>

#include <filesystem>
#include <set>

#include "slamroute/core/DriveGraph.hpp"
#include "slamroute/core/SumoNet.hpp"
#include "slamroute/simulate/Survey.hpp"

namespace {
using namespace slamroute;

SumoNet testNet(const std::string& name) {
  return SumoNet::read(std::filesystem::path(SLAMROUTE_SOURCE_DIR) / "networks" / name);
}

void expectValidCover(const SumoNet& net, double max_len, std::size_t* n_routes = nullptr) {
  const DriveGraph g = DriveGraph::fromNet(net);
  const auto routes = simulate::coveringRoutes(g, max_len);
  std::set<std::size_t> covered;
  for (const auto& r : routes) {
    ASSERT_FALSE(r.empty());
    for (std::size_t i = 0; i < r.size(); ++i) {
      covered.insert(r[i]);
      if (i > 0) {
        EXPECT_TRUE(net.turnAllowed(g.edges[r[i - 1]].sumo_edge, g.edges[r[i]].sumo_edge))
            << g.edges[r[i - 1]].sumo_edge << " -> " << g.edges[r[i]].sumo_edge;
      }
    }
  }
  EXPECT_EQ(covered.size(), g.numEdges()) << net.source;  // strongly connected: everything
  if (n_routes) *n_routes = routes.size();
}

TEST(SurveyRoutes, RingIsOneRouteRoundTheRingAndBack) {
  const SumoNet net = testNet("test/ring.net.xml");
  const auto routes = simulate::coveringRoutes(DriveGraph::fromNet(net), 1e9);
  ASSERT_EQ(routes.size(), 1u);
  // One-way ring: each edge once, then the first again, as the turn from the last edge onto the
  // first is a bend (a junction with two arms) to drive too.
  ASSERT_EQ(routes[0].size(), 9u);
  EXPECT_EQ(routes[0].front(), routes[0].back());
}

TEST(SurveyRoutes, GridIsCoveredByValidRoutes) {
  std::size_t one = 0, many = 0;
  expectValidCover(testNet("test/grid3x3.net.xml"), 1e9, &one);
  expectValidCover(testNet("test/grid3x3.net.xml"), 500.0, &many);
  EXPECT_EQ(one, 1u);  // strongly connected, no length limit: a single route
  EXPECT_GT(many, 1u);
}

TEST(SurveyRoutes, DefaultCityIsCoveredByValidRoutes) {
  expectValidCover(testNet("default_city/default_city.net.xml"), 2000.0);
}

/// A corner B between A and C with U-turns allowed at B, and a one-way link A -> C:
///   0: A->B 10 m, 1: B->A 10 m, 2: C->B 50 m, 3: B->C 50 m, 4: A->C 20 m.
/// Every edge is reachable without driving round B (0, U-turn 1, 4, 2, U-turn 3), which is what
/// the nearest-edge greedy does; the routes must also turn 0 -> 3 and 2 -> 1 at B.
DriveGraph cornerWithUTurns() {
  DriveGraph g;
  for (int v = 0; v < 3; ++v) boost::add_vertex(g.g);
  const std::size_t A = 0, B = 1, C = 2;
  g.edges = {{A, B, "AB", 10.0}, {B, A, "BA", 10.0}, {C, B, "CB", 50.0}, {B, C, "BC", 50.0},
             {A, C, "AC", 20.0}};
  g.allowed_next = {{1, 3}, {0, 4}, {3, 1}, {2}, {2}};
  return g;
}

std::set<std::pair<std::size_t, std::size_t>> turnsDriven(
    const std::vector<std::vector<std::size_t>>& routes) {
  std::set<std::pair<std::size_t, std::size_t>> turns;
  for (const auto& r : routes)
    for (std::size_t i = 1; i < r.size(); ++i) turns.insert({r[i - 1], r[i]});
  return turns;
}

TEST(SurveyRoutes, CornerReachedByUTurnsIsDrivenRound) {
  const DriveGraph g = cornerWithUTurns();
  for (double max_len : {1e9, 30.0}) {
    const auto turns = turnsDriven(simulate::coveringRoutes(g, max_len));
    EXPECT_TRUE(turns.count({0, 3})) << max_len;  // A -> B -> C
    EXPECT_TRUE(turns.count({2, 1})) << max_len;  // C -> B -> A
    EXPECT_TRUE(turns.count({1, 4})) << max_len;  // B -> A -> C: A is a bend too
    EXPECT_TRUE(turns.count({4, 2})) << max_len;  // A -> C -> B
  }
}

TEST(SurveyRoutes, EveryBendOfTheDefaultCityIsDriven) {
  const SumoNet net = testNet("default_city/default_city.net.xml");
  const DriveGraph g = DriveGraph::fromNet(net);
  const auto turns = turnsDriven(simulate::coveringRoutes(g, 2000.0));
  std::vector<std::set<std::size_t>> arms(g.numVertices());
  for (const auto& e : g.edges) {
    arms[e.u].insert(e.v);
    arms[e.v].insert(e.u);
  }
  std::size_t bends = 0;
  for (std::size_t e = 0; e < g.numEdges(); ++e) {
    if (arms[g.edges[e].v].size() != 2) continue;
    for (std::size_t next : g.allowed_next[e]) {
      if (g.edges[next].v == g.edges[e].u) continue;  // U-turn
      ++bends;
      EXPECT_TRUE(turns.count({e, next})) << g.edges[e].sumo_edge << " -> "
                                          << g.edges[next].sumo_edge;
    }
  }
  EXPECT_GE(bends, 8u);  // the city's four corners, both ways
}

}  // namespace
