// Place-level scoring (validateAgainstPlaces) on a hand-made net whose known answer is counted by
// hand: one rule groups the net's junctions and the graph's nodes into places.
//
// The net: a street along y = 0 from P (-200, 0) to E (224, 0) with a staggered pair of T
// junctions on it, A (0, 0) with a side street north to N (0, 200) and B (24, 0) with one south
// to S (24, -200); P, N, E and S are joined in a ring (P - N - E - S - P), so each has three
// neighbours. The A - B edge runs between the two junctions' shapes (x 6 to 18, 12 m), as SUMO
// lays it. Junction level: 6 intersections, 9 chains (A - B one of them). Place level (A and B
// 24 m apart, one place): 5 places, 8 chains.
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "slamroute/core/RoadGraph.hpp"
#include "slamroute/core/SumoNet.hpp"
#include "slamroute/roadgraph/SumoMatch.hpp"

namespace slamroute::roadgraph {
namespace {

void addJunction(SumoNet& net, const std::string& id, double x, double y) {
  SumoJunction j;
  j.id = id;
  j.type = "priority";
  j.pos = Point3(x, y, 0.0);
  net.junction_index[id] = net.junctions.size();
  net.junctions.push_back(j);
}

/// One one-lane passenger edge from -> to along `shape`.
void addEdge(SumoNet& net, const std::string& from, const std::string& to, const Polyline& shape) {
  SumoEdge e;
  e.id = from + "_" + to;
  e.from = from;
  e.to = to;
  e.shape = shape;
  SumoLane lane;
  lane.id = e.id + "_0";
  lane.shape = shape;
  lane.length_m = polylineLength(shape);
  e.lanes.push_back(lane);
  net.edge_index[e.id] = net.edges.size();
  net.edges.push_back(e);
}

Point3 at(const SumoNet& net, const std::string& id) { return net.findJunction(id)->pos; }

/// With `split`, SUMO splits the A - B street at a junction M (12, 0) where its lanes change:
/// M has two neighbours and is no intersection.
SumoNet staggeredNet(bool split = false) {
  SumoNet net;
  addJunction(net, "P", -200, 0);
  addJunction(net, "A", 0, 0);
  addJunction(net, "B", 24, 0);
  addJunction(net, "E", 224, 0);
  addJunction(net, "N", 0, 200);
  addJunction(net, "S", 24, -200);
  if (split) {
    addJunction(net, "M", 12, 0);
    addEdge(net, "A", "M", {Point3(6, 0, 0), Point3(12, 0, 0)});
    addEdge(net, "M", "B", {Point3(12, 0, 0), Point3(18, 0, 0)});
  } else {
    addEdge(net, "A", "B", {Point3(6, 0, 0), Point3(18, 0, 0)});
  }
  for (const char* uv : {"PA", "BE", "AN", "BS", "PN", "NE", "ES", "SP"}) {
    const std::string u(1, uv[0]), v(1, uv[1]);
    addEdge(net, u, v, {at(net, u), at(net, v)});
  }
  return net;
}

/// A graph with one node per (x, y) and one two-way street (two edges) per pair of node indices.
RoadGraph graphOf(const std::vector<std::pair<double, double>>& nodes,
                  const std::vector<std::pair<int, int>>& streets) {
  RoadGraph g;
  for (const auto& [x, y] : nodes)
    g.nodes.push_back({static_cast<int>(g.nodes.size()), Point3(x, y, 0.0), ""});
  for (std::size_t s = 0; s < streets.size(); ++s)
    for (const auto& [u, v] : {streets[s], std::pair{streets[s].second, streets[s].first}}) {
      RoadEdge e;
      e.id = static_cast<int>(g.edges.size());
      e.street = static_cast<int>(s);
      e.u = u;
      e.v = v;
      e.polyline = {g.nodes[static_cast<std::size_t>(u)].pos,
                    g.nodes[static_cast<std::size_t>(v)].pos};
      e.length_m = polylineLength(e.polyline);
      g.edges.push_back(e);
    }
  return g;
}

// The extracted graph as the hollow cylinder gives it at a staggered pair: a node on each T
// (2.2 m from its junction, the two 20.2 m apart) and the short street between them. Nodes:
// 0 P, 1 A, 2 N, 3 E, 4 S, 5 B.
RoadGraph staggeredGraph() {
  return graphOf({{-199, 1}, {2, 1}, {1, 198}, {222, -1}, {25, -198}, {22, -1}},
                 {{0, 1}, {1, 5}, {5, 3}, {1, 2}, {5, 4}, {0, 2}, {2, 3}, {3, 4}, {4, 0}});
}

/// Every intersection found by one detected place and every chain by one street, none false.
void expectAllFound(const ValidationResult& v, std::size_t intersections, std::size_t chains) {
  EXPECT_EQ(v.true_intersections, intersections);
  EXPECT_EQ(v.detected_nodes, intersections);
  EXPECT_EQ(v.matched_nodes, intersections);
  EXPECT_TRUE(v.false_nodes.empty());
  EXPECT_EQ(v.true_chains, chains);
  EXPECT_EQ(v.detected_streets, chains);
  EXPECT_EQ(v.matched_streets, chains);
  EXPECT_EQ(v.found_chains, chains);
}

TEST(PlaceScoring, TwoNodesOfAStaggeredPairAreOneMatchedPlace) {
  const SumoNet net = staggeredNet();
  const RoadGraph g = staggeredGraph();
  // The street between the two nodes lies inside the place and is not counted; the through
  // street's halves (to P and to E) and the side streets (to N and S) each match a chain.
  const auto v = validateAgainstPlaces(g, {}, net, SumoMatchConfig{});
  expectAllFound(v, 5, 8);
  EXPECT_EQ(v.node_junction[1], "A+B");
  EXPECT_EQ(v.node_junction[5], "A+B");
  // The same graph at junction level: each node is its T junction, the short street its chain.
  expectAllFound(validateAgainstNet(g, {}, net, SumoMatchConfig{}), 6, 9);
}

// The rule is the same on both sides: with place_link_max_m below both gaps (24 m between the
// junctions, 20.2 m between the nodes) neither pair is grouped and the scores are the junction
// level's.
TEST(PlaceScoring, PairsFartherApartThanTheLinkMaximumStayTwoPlacesOnBothSides) {
  SumoMatchConfig cfg;
  cfg.place_link_max_m = 15.0;
  expectAllFound(validateAgainstPlaces(staggeredGraph(), {}, staggeredNet(), cfg), 6, 9);
}

// The pair is one place when SUMO splits the street between them too: the rule follows a street
// through junctions that are no intersections, as a graph street spans them.
TEST(PlaceScoring, AStreetSplitBetweenThePairStillJoinsIt) {
  const auto v = validateAgainstPlaces(staggeredGraph(), {}, staggeredNet(true), SumoMatchConfig{});
  expectAllFound(v, 5, 8);
  EXPECT_EQ(v.node_junction[1], "A+B");
}

// A node that no junction lies near (F at (-100, 0) on the street P - A, with a stub to a dead
// end) is far from every other node, so it stays a place of its own and counts as false; the
// two streets it splits P - A into match nothing, the stub (to a dead end) is not counted.
TEST(PlaceScoring, ALoneFalseNodeStillCountsAsFalse) {
  const RoadGraph g = graphOf(
      {{-199, 1}, {2, 1}, {1, 198}, {222, -1}, {25, -198}, {22, -1}, {-100, 0}, {-100, 30}},
      {{0, 6}, {6, 1}, {6, 7}, {1, 5}, {5, 3}, {1, 2}, {5, 4}, {0, 2}, {2, 3}, {3, 4}, {4, 0}});
  std::vector<char> is_end(g.nodes.size(), 0);
  is_end[7] = 1;
  const auto v = validateAgainstPlaces(g, is_end, staggeredNet(), SumoMatchConfig{});
  EXPECT_EQ(v.detected_nodes, 6u);
  EXPECT_EQ(v.matched_nodes, 5u);
  EXPECT_EQ(v.false_nodes, std::vector<int>{6});
  EXPECT_DOUBLE_EQ(v.node_precision, 5.0 / 6.0);
  EXPECT_DOUBLE_EQ(v.node_recall, 1.0);
  EXPECT_EQ(v.detected_streets, 9u);
  EXPECT_EQ(v.matched_streets, 7u);
  EXPECT_EQ(v.found_chains, 7u);
}

}  // namespace
}  // namespace slamroute::roadgraph
