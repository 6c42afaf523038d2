// Turning places (TurningPlaces.cpp) and the validation's streets through bends
// (StreetsThroughBends.cpp), on the turning_place test net: the corner B joins the two-way street
// A-B to the one-way street B -> C, so B_A is entered only by turning round at B. Known answers:
// the graph built from traces that drive round B and turn round there is strongly connected
// under the net's turns, postman on it drives all 13 SUMO edges, and A-B-C is one street of
// the net's chains.
#include <gtest/gtest.h>

#include <filesystem>

#include "LaneTraces.hpp"
#include "StreetsThroughBends.hpp"
#include "slamroute/core/SumoCoverage.hpp"
#include "slamroute/rl/PlanGraph.hpp"
#include "slamroute/rl/Planners.hpp"
#include "slamroute/roadgraph/GraphBuilder.hpp"
#include "slamroute/roadgraph/SumoMatch.hpp"

namespace slamroute::roadgraph {
namespace {

SumoNet turningPlaceNet() {
  return SumoNet::read(std::filesystem::path(SLAMROUTE_SOURCE_DIR) /
                       "networks/test/turning_place.net.xml");
}

/// A survey of the net: round the corner B, turning round at B, and every other street both ways.
GraphBuildResult surveyedGraph(const SumoNet& net) {
  const Traces tr = test::routeTraces(net, {{"W_A", "A_B", "B_C", "C_D", "D_A", "A_W"},
                                            {"N_D", "D_A", "A_B", "B_A", "A_D", "D_N"},
                                            {"E_C", "C_D", "D_N"},
                                            {"N_D", "D_C", "C_E"}});
  GraphBuildResult built = graphFromTraces(tr, Config{});
  mapSumoEdges(built.graph, net, SumoMatchConfig{});
  turnsFromNet(built.graph, net, SumoMatchConfig{});
  return built;
}

TEST(TurningPlaces, CornerWhereVehiclesTurnRoundIsANode) {
  const SumoNet net = turningPlaceNet();
  const GraphBuildResult built = surveyedGraph(net);
  EXPECT_EQ(built.stats.turning_places, 1u);
  EXPECT_EQ(built.stats.intersections, 3u);  // A, C, D
  int place = -1;
  for (std::size_t n = 0; n < built.node_is_end.size(); ++n)
    if (built.node_is_end[n] == kTurningPlace) place = static_cast<int>(n);
  ASSERT_GE(place, 0);
  const Point3& p = built.graph.nodes[static_cast<std::size_t>(place)].pos;
  EXPECT_NEAR(p.x(), 350.0, 10.0);  // at B
  EXPECT_NEAR(p.y(), 150.0, 10.0);
  // A -> B, B -> A (the U-turn-only direction) and B -> C end or start there.
  int in = 0, out = 0;
  for (const auto& e : built.graph.edges) {
    in += e.v == place;
    out += e.u == place;
  }
  EXPECT_EQ(in, 1);
  EXPECT_EQ(out, 2);
}

TEST(TurningPlaces, GraphIsStronglyConnectedAndPostmanDrivesEveryDirectedEdge) {
  const SumoNet net = turningPlaceNet();
  const RoadGraph g = surveyedGraph(net).graph;
  ASSERT_TRUE(g.restricted_turns);
  const rl::PlanGraph pg = rl::PlanGraph::build(g);
  EXPECT_EQ(pg.dropped_edges, 0);
  EXPECT_EQ(pg.dropped_nodes, 0);
  rl::Config cfg;
  cfg.planner = "postman";
  const SumoCoverage c = sumoCoverage(net, rl::plan(g, cfg, 1).sumo_edges);
  EXPECT_EQ(c.edges_total, 13);
  EXPECT_EQ(c.edges_driven, 13);
}

TEST(TurningPlaces, ValidationJoinsTheStreetThroughTheTurningPlace) {
  const SumoNet net = turningPlaceNet();
  const GraphBuildResult built = surveyedGraph(net);
  // The net's chains between its intersections A, C, D: A-B-C (B has two neighbours), C-D, A-D.
  const RoadGraph view = detail::streetsThroughBends(built.graph, built.node_is_end);
  const auto joined = validateAgainstNet(view, built.node_is_end, net, SumoMatchConfig{});
  EXPECT_EQ(joined.true_chains, 3u);
  EXPECT_EQ(joined.found_chains, 3u);
  EXPECT_DOUBLE_EQ(joined.edge_precision, 1.0);
  EXPECT_DOUBLE_EQ(joined.node_f1, 1.0);
  // Unjoined, A-B and B-C end at a node that is not an intersection: the chain A-C is missed.
  const auto split = validateAgainstNet(built.graph, built.node_is_end, net, SumoMatchConfig{});
  EXPECT_EQ(split.found_chains, 2u);
}

/// Nodes 0..4 on a line; kinds per node; streets 0-1 (two-way), 1-2 (one-way), 2-3, 3-4.
RoadGraph lineGraph() {
  RoadGraph g;
  for (int i = 0; i < 5; ++i) g.nodes.push_back({i, Point3(100.0 * i, 0, 0), ""});
  auto add = [&](int u, int v, int street) {
    RoadEdge e;
    e.id = static_cast<int>(g.edges.size());
    e.u = u;
    e.v = v;
    e.street = street;
    e.length_m = 100.0;
    g.edges.push_back(e);
  };
  add(0, 1, 0);
  add(1, 0, 0);
  add(1, 2, 1);
  add(2, 3, 2);
  add(3, 4, 3);
  return g;
}

TEST(StreetsThroughBends, JoinsOnlyThroughTurningPlaces) {
  const RoadGraph g = lineGraph();
  // 1: a turning place, 2: an intersection with two streets, 3: a corner where dead ends met,
  // 4: a dead end.
  const std::vector<char> kind = {kIntersection, kTurningPlace, kIntersection, kDeadEnd, kDeadEnd};
  const RoadGraph view = detail::streetsThroughBends(g, kind);
  ASSERT_EQ(view.edges.size(), 3u);  // 0-2 through 1; 2-3; 3-4
  EXPECT_EQ(std::min(view.edges[0].u, view.edges[0].v), 0);
  EXPECT_EQ(std::max(view.edges[0].u, view.edges[0].v), 2);
  EXPECT_DOUBLE_EQ(view.edges[0].length_m, 200.0);
  EXPECT_EQ(view.edges[1].u, 2);
  EXPECT_EQ(view.edges[1].v, 3);
  EXPECT_EQ(view.nodes.size(), g.nodes.size());
  // All intersections: nothing is joined.
  EXPECT_EQ(detail::streetsThroughBends(g, std::vector<char>(5, kIntersection)).edges.size(), 4u);
}

}  // namespace
}  // namespace slamroute::roadgraph
