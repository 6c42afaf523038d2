#include <gtest/gtest.h>

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/strong_components.hpp>

#include "slamroute/core/SyntheticCity.hpp"

namespace slamroute {
namespace {

TEST(SyntheticCity, SizeConnectivityAndDeterminism) {
  for (int n : {10, 50, 500}) {
    SyntheticCityConfig cfg;
    cfg.nodes = n;
    const RoadGraph g = syntheticCity(cfg, 7);
    ASSERT_EQ(static_cast<int>(g.nodes.size()), n);
    g.validate("synthetic");
    boost::adjacency_list<boost::vecS, boost::vecS, boost::directedS> bg(g.nodes.size());
    for (const auto& e : g.edges) boost::add_edge(e.u, e.v, bg);
    std::vector<int> comp(g.nodes.size());
    EXPECT_EQ(boost::strong_components(bg, comp.data()), 1) << "n=" << n;
    const RoadGraph again = syntheticCity(cfg, 7);
    ASSERT_EQ(again.edges.size(), g.edges.size());
    for (std::size_t i = 0; i < g.edges.size(); ++i) EXPECT_EQ(again.edges[i].weight, g.edges[i].weight);
  }
}

}  // namespace
}  // namespace slamroute
