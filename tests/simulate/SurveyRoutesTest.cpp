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

/// A corner B between A and C with U-turns allowed at B, a one-way link A -> C and a street D -> A
/// (A has three arms, so no bend of its own):
///   0: A->B 10 m, 1: B->A 10 m, 2: C->B 50 m, 3: B->C 50 m, 4: A->C 20 m, 5: D->A 5 m.
/// Every edge is reachable without driving round B (5, 0, U-turn 1, 4, 2, U-turn 3), which is
/// what the nearest-edge greedy does; the routes must also turn 0 -> 3 and 2 -> 1 at B.
DriveGraph cornerWithUTurns() {
  DriveGraph g;
  for (int v = 0; v < 4; ++v) boost::add_vertex(g.g);
  const std::size_t A = 0, B = 1, C = 2, D = 3;
  g.edges = {{A, B, "AB", 10.0}, {B, A, "BA", 10.0}, {C, B, "CB", 50.0},
             {B, C, "BC", 50.0}, {A, C, "AC", 20.0}, {D, A, "DA", 5.0}};
  g.allowed_next = {{1, 3}, {0, 4}, {3, 1}, {2}, {2}, {0, 4}};
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
    const auto routes = simulate::coveringRoutes(g, max_len);
    const auto turns = turnsDriven(routes);
    EXPECT_TRUE(turns.count({0, 3})) << max_len;  // A -> B -> C
    EXPECT_TRUE(turns.count({2, 1})) << max_len;  // C -> B -> A
    std::set<std::size_t> edges;
    for (const auto& r : routes) edges.insert(r.begin(), r.end());
    EXPECT_EQ(edges.size(), g.numEdges()) << max_len;
  }
}

/// SUMO edge ids of the turns the covering routes drive.
std::set<std::pair<std::string, std::string>> sumoTurnsDriven(const DriveGraph& g,
                                                              double max_length_m) {
  std::set<std::pair<std::string, std::string>> turns;
  for (const auto& [a, b] : turnsDriven(simulate::coveringRoutes(g, max_length_m)))
    turns.insert({g.edges[a].sumo_edge, g.edges[b].sumo_edge});
  return turns;
}

TEST(SurveyRoutes, DefaultCityBendsAreDrivenTurningPlacesToo) {
  const DriveGraph g = DriveGraph::fromNet(testNet("default_city/default_city.net.xml"));
  const auto turns = sumoTurnsDriven(g, 2000.0);
  // The bends of the city's two-arm junctions R0C0, R0C2 and R4C5, and of R0C1, R0C5 and R4C0,
  // corners where a two-way street meets a one-way street (turning places: one direction of the
  // two-way street can only turn round there, and the road graph gives them a node).
  for (const auto& [a, b] :
       std::vector<std::pair<std::string, std::string>>{{"R0C1_R0C0", "R0C0_R1C0"},
                                                        {"R1C0_R0C0", "R0C0_R0C1"},
                                                        {"T2_R0C2", "R0C2_R1C2"},
                                                        {"R1C2_R0C2", "R0C2_T2"},
                                                        {"R3C5_R4C5", "R4C5_R4C4"},
                                                        {"R0C0_R0C1", "R0C1_R1C1"},
                                                        {"R0C4_R0C5", "R0C5_R2C5"},
                                                        {"R4C2_R4C0", "R4C0_R3C0"}})
    EXPECT_TRUE(turns.count({a, b})) << a << " -> " << b;
}

}  // namespace
