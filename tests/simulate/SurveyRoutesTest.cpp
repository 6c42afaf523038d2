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

TEST(SurveyRoutes, RingIsOneRouteOfEightEdges) {
  const SumoNet net = testNet("test/ring.net.xml");
  const auto routes = simulate::coveringRoutes(DriveGraph::fromNet(net), 1e9);
  ASSERT_EQ(routes.size(), 1u);
  EXPECT_EQ(routes[0].size(), 8u);  // one-way ring: each edge exactly once
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

}  // namespace
