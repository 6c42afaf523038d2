// Divided roads (roadgraph/src/DividedRoads.cpp) on the shipped 3 x 3 grids whose middle row (and
// column) is a divided avenue (networks/generate.py, divided_grid_net), driven by lane traces
// (every lane and connection twice: a link between two junctions needs two vehicles each way).
// Known answers: the places are the two T junctions on the outer rows and the avenue's three
// crossings (its carriageways' junctions, 16 or 20 m apart, are one place each): 5 nodes; the
// streets between them are the 4 halves of the middle row and column and the 4 L-shaped
// streets round the grid's corners: 8 streets, each two-way (16 directed edges).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "DividedRoads.hpp"
#include "LaneTraces.hpp"
#include "slamroute/core/SumoNet.hpp"
#include "slamroute/roadgraph/GraphBuilder.hpp"
#include "slamroute/roadgraph/SumoMatch.hpp"

namespace slamroute::roadgraph {
namespace {

namespace fs = std::filesystem;

SumoNet shippedNet(const std::string& name) {
  return SumoNet::read(fs::path(SLAMROUTE_SOURCE_DIR) / "networks/test" / (name + ".net.xml"));
}

const RoadNode* nodeNear(const RoadGraph& g, double x, double y, double radius_m) {
  for (const auto& n : g.nodes)
    if ((n.pos.head<2>() - Eigen::Vector2d(x, y)).norm() <= radius_m) return &n;
  return nullptr;
}

/// The graph's edge from the node near a to the node near b (nullptr when none).
const RoadEdge* edgeBetween(const RoadGraph& g, Eigen::Vector2d a, Eigen::Vector2d b) {
  const RoadNode* u = nodeNear(g, a.x(), a.y(), 6.0);
  const RoadNode* v = nodeNear(g, b.x(), b.y(), 6.0);
  if (!u || !v) return nullptr;
  for (const auto& e : g.edges)
    if (e.u == u->id && e.v == v->id) return &e;
  return nullptr;
}

void expectPlaces(const std::string& name, int divided_streets) {
  const SumoNet net = shippedNet(name);
  const auto built = graphFromTraces(test::laneTraces(net, 0.5, 42, 2), Config{});
  const RoadGraph& g = built.graph;
  EXPECT_EQ(g.nodes.size(), 5u) << name;
  EXPECT_EQ(std::count(built.node_is_end.begin(), built.node_is_end.end(), 1), 0) << name;
  for (const auto& [x, y] :
       {std::pair{300.0, 100.0}, {300.0, 500.0}, {100.0, 300.0}, {300.0, 300.0}, {500.0, 300.0}})
    EXPECT_NE(nodeNear(g, x, y, 6.0), nullptr) << name << ": no node at (" << x << ", " << y << ")";
  EXPECT_EQ(built.stats.streets, 8u) << name;
  EXPECT_EQ(g.edges.size(), 16u) << name;
  EXPECT_EQ(built.stats.divided_streets, static_cast<std::size_t>(divided_streets)) << name;
  const auto v = validateAgainstPlaces(g, built.node_is_end, net, SumoMatchConfig{});
  EXPECT_EQ(v.true_intersections, 5u) << name;
  EXPECT_DOUBLE_EQ(v.node_f1, 1.0) << name;
  EXPECT_EQ(v.true_chains, 8u) << name;
  EXPECT_DOUBLE_EQ(v.edge_precision, 1.0) << name;
  EXPECT_DOUBLE_EQ(v.edge_recall, 1.0) << name;
}

// The place-level truth of the divided-avenue net, scored with the graph it should give: the five
// places and the eight streets between them score 1; at junction level the same graph finds 5 of
// the 8 SUMO intersections (each carriageway crossing is one) and not all of the 13 chains.
TEST(DividedRoads, PlaceLevelTruthOfTheDividedAvenueNet) {
  const SumoNet net = shippedNet("divided_avenue");
  RoadGraph g;
  for (const auto& [x, y] :
       {std::pair{300.0, 100.0}, {300.0, 500.0}, {100.0, 300.0}, {300.0, 300.0}, {500.0, 300.0}})
    g.nodes.push_back({static_cast<int>(g.nodes.size()), Point3(x, y, 0.0), ""});
  for (const auto& [u, v] :
       {std::pair{0, 3}, {1, 3}, {2, 3}, {3, 4}, {0, 2}, {0, 4}, {1, 2}, {1, 4}}) {
    RoadEdge e;
    e.id = e.street = static_cast<int>(g.edges.size());
    e.u = u;
    e.v = v;
    g.edges.push_back(e);
  }
  const auto places = validateAgainstPlaces(g, {}, net, SumoMatchConfig{});
  EXPECT_EQ(places.true_intersections, 5u);
  EXPECT_EQ(places.true_chains, 8u);
  EXPECT_DOUBLE_EQ(places.node_f1, 1.0);
  EXPECT_DOUBLE_EQ(places.edge_precision, 1.0);
  EXPECT_DOUBLE_EQ(places.edge_recall, 1.0);
  const auto junctions = validateAgainstNet(g, {}, net, SumoMatchConfig{});
  EXPECT_EQ(junctions.true_intersections, 8u);
  EXPECT_EQ(junctions.true_chains, 13u);
  EXPECT_EQ(junctions.matched_nodes, 5u);
  EXPECT_LT(junctions.found_chains, 13u);
}

TEST(DividedRoads, DividedAvenueIsOneStreetWithOneNodePerCrossing) {
  expectPlaces("divided_avenue", 2);
}

TEST(DividedRoads, CrossingOfTwoDividedAvenuesIsOneNode) { expectPlaces("divided_cross", 4); }

// Each direction of a divided street keeps its own carriageway: SUMO lays the two 3.2 m lanes of
// a one-way edge to the right of its line, so the eastbound lanes' middle is y = 292 - 3.2 and
// the westbound one y = 308 + 3.2; each direction maps onto its own SUMO edge.
TEST(DividedRoads, EachDirectionDrivesItsOwnCarriageway) {
  const SumoNet net = shippedNet("divided_avenue");
  auto built = graphFromTraces(test::laneTraces(net, 0.5, 42, 2), Config{});
  mapSumoEdges(built.graph, net, SumoMatchConfig{});
  const RoadEdge* east = edgeBetween(built.graph, {100, 300}, {300, 300});
  const RoadEdge* west = edgeBetween(built.graph, {300, 300}, {100, 300});
  ASSERT_NE(east, nullptr);
  ASSERT_NE(west, nullptr);
  EXPECT_EQ(east->street, west->street);
  const auto middle = [](const RoadEdge& e) { return e.polyline[e.polyline.size() / 2]; };
  EXPECT_NEAR(middle(*east).y(), 288.8, 1.5);
  EXPECT_NEAR(middle(*west).y(), 311.2, 1.5);
  EXPECT_EQ(east->sumo_edges, std::vector<std::string>{"g10s_g11s"});
  EXPECT_EQ(west->sumo_edges, std::vector<std::string>{"g11n_g10n"});
}

RoadEdge straightEdge(int id, int street, int u, int v, const Point3& a, const Point3& b) {
  RoadEdge e;
  e.id = id;
  e.street = street;
  e.u = u;
  e.v = v;
  for (int k = 0; k <= 10; ++k) e.polyline.push_back(a + (b - a) * (k / 10.0));
  e.length_m = polylineLength(e.polyline);
  return e;
}

// The merge on a hand-made graph: carriageways y = -8 (eastbound) and y = +8 (westbound) between
// x = 0 and x = 200, crossing streets joining the two carriageway nodes at each end (two-way),
// and a two-way side street from the east place north to (200, 100). Known answer: the four
// carriageway nodes become two at (0, 0) and (200, 0), the crossing streets inside them go, the
// carriageways are one street whose edges start and end at the merged nodes.
TEST(DividedRoads, CarriagewayNodesMergeIntoOnePlaceEach) {
  GraphBuildResult out;
  RoadGraph& g = out.graph;
  const std::vector<Point3> pos = {{0, -8, 0}, {0, 8, 0}, {200, -8, 0}, {200, 8, 0}, {200, 100, 0}};
  for (std::size_t k = 0; k < pos.size(); ++k) g.nodes.push_back({static_cast<int>(k), pos[k], ""});
  out.node_is_end = {0, 0, 0, 0, 1};
  g.edges = {straightEdge(0, 0, 0, 2, pos[0], pos[2]), straightEdge(1, 1, 3, 1, pos[3], pos[1]),
             straightEdge(2, 2, 0, 1, pos[0], pos[1]), straightEdge(3, 2, 1, 0, pos[1], pos[0]),
             straightEdge(4, 3, 2, 3, pos[2], pos[3]), straightEdge(5, 3, 3, 2, pos[3], pos[2]),
             straightEdge(6, 4, 3, 4, pos[3], pos[4]), straightEdge(7, 4, 4, 3, pos[4], pos[3])};
  detail::mergeDividedRoads(out, DividedRoadConfig{}, 5.0);
  ASSERT_EQ(g.nodes.size(), 3u);
  EXPECT_EQ(out.stats.divided_node_pairs, 2u);
  EXPECT_EQ(out.stats.divided_streets, 1u);
  EXPECT_EQ(out.stats.intersections, 2u);
  EXPECT_EQ(out.stats.streets, 2u);
  EXPECT_TRUE(g.nodes[0].pos.isApprox(Point3(0, 0, 0)));
  EXPECT_TRUE(g.nodes[1].pos.isApprox(Point3(200, 0, 0)));
  ASSERT_EQ(g.edges.size(), 4u);  // the two carriageways and the side street's two directions
  const RoadEdge &east = g.edges[0], &west = g.edges[1];
  EXPECT_EQ(east.u, 0);
  EXPECT_EQ(east.v, 1);
  EXPECT_EQ(west.u, 1);
  EXPECT_EQ(west.v, 0);
  EXPECT_EQ(east.street, west.street);
  EXPECT_TRUE(east.polyline.front().isApprox(g.nodes[0].pos));
  EXPECT_TRUE(west.polyline.back().isApprox(g.nodes[0].pos));
  EXPECT_NEAR(east.polyline[5].y(), -8.0, 1e-9);  // each direction keeps its carriageway
  EXPECT_NEAR(west.polyline[5].y(), 8.0, 1e-9);
  EXPECT_EQ(g.edges[2].u, 1);  // the side street now leaves the east place
  g.validate("merged graph");
}

// Without the merge each carriageway crossing is a node of its own: the junction-level answer.
TEST(DividedRoads, WithoutTheMergeEachCarriagewayCrossingIsANode) {
  const SumoNet net = shippedNet("divided_avenue");
  Config cfg;
  cfg.divided.enabled = false;
  const auto built = graphFromTraces(test::laneTraces(net, 0.5, 42, 2), cfg);
  EXPECT_EQ(built.graph.nodes.size(), 8u);
  const auto v = validateAgainstNet(built.graph, built.node_is_end, net, SumoMatchConfig{});
  EXPECT_EQ(v.true_intersections, 8u);
  EXPECT_DOUBLE_EQ(v.node_f1, 1.0);
}

}  // namespace
}  // namespace slamroute::roadgraph
