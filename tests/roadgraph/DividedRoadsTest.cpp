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

/// Two-way straight streets between the given nodes; node_is_end marks the dead ends.
GraphBuildResult twoWayGraph(const std::vector<Point3>& pos, std::vector<char> node_is_end,
                             const std::vector<std::pair<int, int>>& streets) {
  GraphBuildResult out;
  RoadGraph& g = out.graph;
  for (std::size_t k = 0; k < pos.size(); ++k) g.nodes.push_back({static_cast<int>(k), pos[k], ""});
  out.node_is_end = std::move(node_is_end);
  for (const auto& [u, v] : streets) {
    const int street = static_cast<int>(g.edges.size()) / 2;
    const auto a = static_cast<std::size_t>(u), b = static_cast<std::size_t>(v);
    g.edges.push_back(straightEdge(static_cast<int>(g.edges.size()), street, u, v, pos[a], pos[b]));
    g.edges.push_back(straightEdge(static_cast<int>(g.edges.size()), street, v, u, pos[b], pos[a]));
  }
  return out;
}

/// A through street along y = 0 from A (-200, 0) over P (0, 0) and Q (32, 0) to B (232, 0), with
/// a side street from P to (0, 150 * side_p) and one from Q to (32 + q_dx, 150 * side_q); the
/// far ends are dead ends.
GraphBuildResult staggeredGraph(double side_p, double side_q, double q_dx = 0.0) {
  return twoWayGraph({{-200, 0, 0},
                      {0, 0, 0},
                      {32, 0, 0},
                      {232, 0, 0},
                      {0, 150 * side_p, 0},
                      {32 + q_dx, 150 * side_q, 0}},
                     {1, 0, 0, 1, 1, 1}, {{0, 1}, {1, 2}, {2, 3}, {1, 4}, {2, 5}});
}

DividedRoadConfig staggerConfig(double max_gap_m = 40.0) {
  DividedRoadConfig cfg;
  cfg.stagger_max_gap_m = max_gap_m;
  return cfg;
}

TEST(DividedRoads, StaggeredTJunctionsAreOnePlace) {
  GraphBuildResult out = staggeredGraph(1.0, -1.0);
  detail::mergeDividedRoads(out, staggerConfig(), 5.0);
  const RoadGraph& g = out.graph;
  EXPECT_EQ(out.stats.staggered_node_pairs, 1u);
  ASSERT_EQ(g.nodes.size(), 5u);
  EXPECT_NE(nodeNear(g, 0, 0, 0.1), nullptr);
  EXPECT_EQ(nodeNear(g, 32, 0, 10.0), nullptr);
  EXPECT_EQ(g.edges.size(), 8u);
  EXPECT_EQ(out.stats.intersections, 1u);
  EXPECT_EQ(out.stats.streets, 4u);
  EXPECT_NE(edgeBetween(g, {0, 0}, {32, -150}), nullptr);
  EXPECT_NE(edgeBetween(g, {232, 0}, {0, 0}), nullptr);
  g.validate("merged staggered graph");
  GraphBuildResult kept = staggeredGraph(1.0, -1.0);
  detail::mergeDividedRoads(kept, DividedRoadConfig{}, 5.0);  // off by default
  EXPECT_EQ(kept.graph.nodes.size(), 6u);
}

// Not staggered pairs, so two places each: both side streets on the same side (two T junctions
// along one kerb), Q's side street running on nearly straight (a fork, not a T), and the pair
// farther apart than stagger_max_gap_m.
TEST(DividedRoads, TJunctionsOnOneSideOrFarApartStayTwoPlaces) {
  for (const auto& [name, out] :
       {std::pair{"same side", staggeredGraph(1.0, 1.0)},
        {"side arm straight on", staggeredGraph(1.0, -1.0 / 150.0, 300)}}) {
    GraphBuildResult merged = out;
    detail::mergeDividedRoads(merged, staggerConfig(), 5.0);
    EXPECT_EQ(merged.stats.staggered_node_pairs, 0u) << name;
    EXPECT_EQ(merged.graph.nodes.size(), 6u) << name;
  }
  GraphBuildResult far = staggeredGraph(1.0, -1.0);
  detail::mergeDividedRoads(far, staggerConfig(30.0), 5.0);
  EXPECT_EQ(far.graph.nodes.size(), 6u);
}

// A street that jogs: from A (-200, 0) east through the T at P (0, 0), whose side street goes
// north, to Q (32, 0) on a north-south street, where it ends (Q is a T whose side arm is P - Q).
// Known answer: with stagger_jogs one node at P (Q's position is given up: both have 6 edges,
// the lower id keeps its own), its arms west, north and Q's north and south; without, two.
TEST(DividedRoads, StreetJoggingAcrossACrossingStreetIsOnePlaceWithJogs) {
  const auto jogGraph = [] {
    return twoWayGraph(
        {{-200, 0, 0}, {0, 0, 0}, {32, 0, 0}, {0, 150, 0}, {32, 150, 0}, {32, -150, 0}},
        {1, 0, 0, 1, 1, 1}, {{0, 1}, {1, 2}, {1, 3}, {2, 4}, {2, 5}});
  };
  GraphBuildResult plain = jogGraph();
  detail::mergeDividedRoads(plain, staggerConfig(), 5.0);
  EXPECT_EQ(plain.graph.nodes.size(), 6u);
  DividedRoadConfig cfg = staggerConfig();
  cfg.stagger_jogs = true;
  GraphBuildResult jog = jogGraph();
  detail::mergeDividedRoads(jog, cfg, 5.0);
  EXPECT_EQ(jog.stats.staggered_node_pairs, 1u);
  ASSERT_EQ(jog.graph.nodes.size(), 5u);
  EXPECT_NE(nodeNear(jog.graph, 0, 0, 0.1), nullptr);
  EXPECT_NE(edgeBetween(jog.graph, {0, 0}, {32, -150}), nullptr);
  EXPECT_NE(edgeBetween(jog.graph, {32, 150}, {0, 0}), nullptr);
  EXPECT_EQ(jog.graph.edges.size(), 8u);
  // Two stems (a short street between two parallel streets) stay two places.
  GraphBuildResult rung =
      twoWayGraph({{0, -150, 0}, {0, 0, 0}, {32, 0, 0}, {0, 150, 0}, {32, 150, 0}, {32, -150, 0}},
                  {1, 0, 0, 1, 1, 1}, {{0, 1}, {1, 2}, {1, 3}, {2, 4}, {2, 5}});
  detail::mergeDividedRoads(rung, cfg, 5.0);
  EXPECT_EQ(rung.graph.nodes.size(), 6u);
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
