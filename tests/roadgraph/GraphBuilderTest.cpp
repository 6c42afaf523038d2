// Streets, dead ends and directions of travel (paper §3.1 steps 2-3) on synthetic traces.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "SyntheticTraces.hpp"
#include "slamroute/roadgraph/GraphBuilder.hpp"

namespace slamroute::roadgraph {
namespace {

using testing::gridRoads;
using testing::line;
using testing::makeTraces;
using testing::plusRoads;
using testing::Road;

std::size_t countStreets(const RoadGraph& g) {
  std::set<int> s;
  for (const auto& e : g.edges) s.insert(e.street);
  return s.size();
}

TEST(GraphBuilder, PlusHasOneIntersectionFourStreetsFourDeadEnds) {
  const auto r = graphFromTraces(makeTraces(plusRoads()), Config{});
  EXPECT_EQ(r.stats.intersections, 1u);
  EXPECT_EQ(r.stats.dead_ends, 4u);
  EXPECT_EQ(countStreets(r.graph), 4u);
  EXPECT_EQ(r.graph.edges.size(), 8u);  // all two-way
  int centre = -1;
  for (std::size_t n = 0; n < r.graph.nodes.size(); ++n)
    if (!r.node_is_end[n]) centre = static_cast<int>(n);
  ASSERT_GE(centre, 0);
  for (const auto& e : r.graph.edges) {
    EXPECT_TRUE(e.u == centre || e.v == centre);
    EXPECT_NEAR(e.length_m, 100.0, 6.0);  // centre to the end of the arm
    EXPECT_NEAR(e.polyline.front().x(), r.graph.nodes[static_cast<std::size_t>(e.u)].pos.x(), 1e-9);
    EXPECT_NEAR(e.polyline.back().y(), r.graph.nodes[static_cast<std::size_t>(e.v)].pos.y(), 1e-9);
  }
}

TEST(GraphBuilder, ClosedGridHasFiveNodesAndEightStreets) {
  // 3x3 junction grid whose outer lines end at the corners: corners are bends, not nodes, so the
  // graph is the centre crossing, 4 T junctions, 4 spokes and 4 ring streets round the corners.
  const auto r = graphFromTraces(makeTraces(gridRoads(3, 100, 0)), Config{});
  EXPECT_EQ(r.stats.intersections, 5u);
  EXPECT_EQ(r.stats.dead_ends, 0u);
  EXPECT_EQ(countStreets(r.graph), 8u);
  double ring = 0;
  for (const auto& e : r.graph.edges)
    if (e.length_m > 150) ring += e.length_m;
  EXPECT_NEAR(ring, 8 * 200.0, 8 * 8.0);  // 4 ring streets x 2 directions, 200 m each
}

TEST(GraphBuilder, GridWithOverhangHasNineIntersectionsAndTwelveDeadEnds) {
  const auto r = graphFromTraces(makeTraces(gridRoads(3, 100, 50), 1.0, 11), Config{});
  EXPECT_EQ(r.stats.intersections, 9u);
  EXPECT_EQ(r.stats.dead_ends, 12u);
  EXPECT_EQ(countStreets(r.graph), 24u);
  EXPECT_NO_THROW(r.graph.validate("grid"));
}

TEST(GraphBuilder, OneWayStreetIsOneDirectedEdge) {
  // Plus whose east arm is only driven eastwards (away from the centre).
  std::vector<Road> roads = {{line({-100, 0, 0}, {0, 0, 0})},
                             {line({0, 0, 0}, {100, 0, 0}), /*two_way=*/false},
                             {line({0, -100, 0}, {0, 100, 0})}};
  const auto r = graphFromTraces(makeTraces(roads, 0.5, 3), Config{});
  EXPECT_EQ(r.stats.one_way_streets, 1u);
  EXPECT_EQ(r.graph.edges.size(), 7u);
  int east = 0;
  for (const auto& e : r.graph.edges) {
    const auto& u = r.graph.nodes[static_cast<std::size_t>(e.u)].pos;
    const auto& v = r.graph.nodes[static_cast<std::size_t>(e.v)].pos;
    if (u.x() > 50 || v.x() > 50) {
      ++east;
      EXPECT_LT(u.x(), v.x()) << "one-way edge must run eastwards";
    }
  }
  EXPECT_EQ(east, 1);
}

TEST(GraphBuilder, DeadEndDrivenInAndBackInOneRunIsTwoWay) {
  // The east arm's only vehicle drives to its end, turns round and comes back: one run, both
  // directions of travel, so the dead end is not a one-way trap.
  std::vector<Road> roads = {{line({-100, 0, 0}, {0, 0, 0})},
                             {{{0, 0, 0}, {100, 0, 0}, {0, 0, 0}}, /*two_way=*/false},
                             {line({0, -100, 0}, {0, 100, 0})}};
  const auto r = graphFromTraces(makeTraces(roads, 0.5, 3), Config{});
  EXPECT_EQ(r.stats.one_way_streets, 0u);
  EXPECT_EQ(r.graph.edges.size(), 8u);
}

TEST(GraphBuilder, CornerNoVehicleDroveRoundKeepsItsStreetsConnected) {
  // The east arm ends 12 m short of a street running north that no vehicle entered from the
  // arm: two dead ends 13 m apart are one corner node.
  const std::vector<Road> roads = {{line({-100, 0, 0}, {100, 0, 0})},
                                   {line({0, -100, 0}, {0, 100, 0})},
                                   {line({108, 10, 0}, {108, 200, 0})}};
  const auto tr = makeTraces(roads, 0.5, 3);
  const auto r = graphFromTraces(tr, Config{});
  EXPECT_EQ(r.stats.merged_end_pairs, 1u);
  EXPECT_EQ(r.stats.dead_ends, 5u);  // west, south, north, top of the north street, corner
  EXPECT_EQ(countStreets(r.graph), 5u);
  int corner = -1;
  for (std::size_t n = 0; n < r.graph.nodes.size(); ++n) {
    int deg = 0;
    for (const auto& e : r.graph.edges)
      deg += (e.u == static_cast<int>(n)) + (e.v == static_cast<int>(n));
    if (r.node_is_end[n] && deg == 4) corner = static_cast<int>(n);
  }
  ASSERT_GE(corner, 0) << "the corner node joins two two-way streets";
  EXPECT_NEAR(r.graph.nodes[static_cast<std::size_t>(corner)].pos.x(), 104.0, 5.0);
  EXPECT_NEAR(r.graph.nodes[static_cast<std::size_t>(corner)].pos.y(), 5.0, 5.0);

  Config off;
  off.edges.end_merge_m = 0.0;
  const auto apart = graphFromTraces(tr, off);
  EXPECT_EQ(apart.stats.merged_end_pairs, 0u);
  EXPECT_EQ(apart.stats.dead_ends, 6u);
}

/// Node ids of the intersection nodes nearest to (x, y), -1 when none is within 8 m.
int intersectionNear(const GraphBuildResult& r, double x, double y) {
  for (std::size_t n = 0; n < r.graph.nodes.size(); ++n)
    if (!r.node_is_end[n] &&
        std::hypot(r.graph.nodes[n].pos.x() - x, r.graph.nodes[n].pos.y() - y) < 8)
      return static_cast<int>(n);
  return -1;
}

bool hasEdge(const RoadGraph& g, int u, int v) {
  for (const auto& e : g.edges)
    if (e.u == u && e.v == v) return true;
  return false;
}

TEST(GraphBuilder, StreetWhoseLanesJoinOnlyNearOneEndIsOneTwoWayStreet) {
  // Junctions A (0, 0) and B (200, 0). Between them the two directions are separate lanes 6 m
  // apart that come together only in the last 30 m before B: the street points form one U-shaped
  // cluster whose two geodesic ends both lie at A. It was dropped as a corner cut.
  const double h = 1.4;  // + 1.6 m right-hand lane offset = lanes at y = -3 and y = +3
  const std::vector<Road> roads = {
      {line({0, -100, 0}, {0, 100, 0})},
      {line({-100, 0, 0}, {0, 0, 0})},
      {line({200, -100, 0}, {200, 100, 0})},
      {line({200, 0, 0}, {300, 0, 0})},
      {{{0, -h, 0}, {170, -h, 0}, {200, 0, 0}}, /*two_way=*/false},  // eastbound lane
      {{{200, 0, 0}, {170, h, 0}, {0, h, 0}}, /*two_way=*/false}};   // westbound lane
  const auto r = graphFromTraces(makeTraces(roads, 0.5, 3), Config{});
  const int a = intersectionNear(r, 0, 0), b = intersectionNear(r, 200, 0);
  ASSERT_GE(a, 0);
  ASSERT_GE(b, 0);
  EXPECT_TRUE(hasEdge(r.graph, a, b)) << "eastbound A -> B missing";
  EXPECT_TRUE(hasEdge(r.graph, b, a)) << "westbound B -> A missing";
  EXPECT_EQ(r.stats.dropped_fragments, 0u);
  EXPECT_EQ(r.stats.u_turn_streets, 1u);
  for (const auto& e : r.graph.edges)
    if ((e.u == a && e.v == b) || (e.u == b && e.v == a)) {
      EXPECT_NEAR(e.length_m, 200.0, 10.0);
    }
}

TEST(GraphBuilder, JunctionsCloserThanTheClearedRadiiAreLinked) {
  // Two crossings 26 m apart on one east-west road: the clearing (12 m round each node) leaves
  // 2 m of that road, too few points for a street. Vehicles drive from one junction straight into
  // the other, so the link is an edge; the one-way variant gets one directed edge.
  for (const bool two_way : {true, false}) {
    const std::vector<Road> roads = {{line({-100, 0, 0}, {0, 0, 0})},
                                     {line({0, 0, 0}, {26, 0, 0}), two_way},
                                     {line({26, 0, 0}, {126, 0, 0})},
                                     {line({0, -100, 0}, {0, 100, 0})},
                                     {line({26, -100, 0}, {26, 100, 0})}};
    const Traces tr = makeTraces(roads, 0.5, 3, 1.0, /*passes=*/2);  // 2 vehicles per direction
    const auto r = graphFromTraces(tr, Config{});
    const int a = intersectionNear(r, 0, 0), b = intersectionNear(r, 26, 0);
    ASSERT_GE(a, 0) << "two_way " << two_way;
    ASSERT_GE(b, 0) << "two_way " << two_way;
    EXPECT_TRUE(hasEdge(r.graph, a, b)) << "two_way " << two_way;
    EXPECT_EQ(hasEdge(r.graph, b, a), two_way) << "two_way " << two_way;
    EXPECT_EQ(r.stats.short_links, 1u);
    Config off;
    off.edges.link_max_m = 0.0;
    const auto apart = graphFromTraces(tr, off);
    EXPECT_EQ(apart.stats.short_links, 0u);
    EXPECT_FALSE(hasEdge(apart.graph, a, b));
  }
}

TEST(GraphBuilder, ShortStreetGetsItsDirectionsFromDrivesBetweenItsJunctions) {
  // Crossings 30 m apart: 6 m of the street between them is left outside the cleared disks, too
  // little for a run to progress min_run_m (8 m), so no run showed a direction and the street
  // was assumed two-way even when driven one way only. Drives from one junction to the other
  // over the street's points give its directions.
  for (const bool two_way : {true, false}) {
    const std::vector<Road> roads = {{line({-100, 0, 0}, {0, 0, 0})},
                                     {line({0, 0, 0}, {30, 0, 0}), two_way},
                                     {line({30, 0, 0}, {130, 0, 0})},
                                     {line({0, -100, 0}, {0, 100, 0})},
                                     {line({30, -100, 0}, {30, 100, 0})}};
    const auto r = graphFromTraces(makeTraces(roads, 0.5, 3, 1.0, /*passes=*/2), Config{});
    const int a = intersectionNear(r, 0, 0), b = intersectionNear(r, 30, 0);
    ASSERT_GE(a, 0) << "two_way " << two_way;
    ASSERT_GE(b, 0) << "two_way " << two_way;
    EXPECT_EQ(r.stats.short_links, 0u) << "a street, not a link";
    EXPECT_EQ(r.stats.unknown_direction_streets, 0u) << "two_way " << two_way;
    EXPECT_TRUE(hasEdge(r.graph, a, b)) << "two_way " << two_way;
    EXPECT_EQ(hasEdge(r.graph, b, a), two_way) << "two_way " << two_way;
  }
}

TEST(GraphBuilder, StreetRunningThroughAJunctionWhoseNodeLiesOffItIsSplitThere) {
  // Junction H (arms north, north-east, north-west) at (100, 15) joined by a 15 m connector to the
  // main road A (0, 0) - B (200, 0). The connector's T and H are one node, voted 15-18 m north of
  // the main road, which is then not cleared there: its cluster runs from A to B past the node.
  // Vehicles drive between the main road and H over the connector, so the road is split at H
  // (A-H, H-B). Without the connector (a road merely passing 15 m from a junction) it stays one
  // street A-B.
  for (const bool connected : {true, false}) {
    std::vector<Road> roads = {
        {line({-100, 0, 0}, {300, 0, 0})},     {line({0, -100, 0}, {0, 100, 0})},
        {line({200, -100, 0}, {200, 100, 0})}, {line({100, 15, 0}, {100, 150, 0})},
        {line({100, 15, 0}, {170, 99, 0})},    {line({100, 15, 0}, {30, 99, 0})}};
    if (connected) roads.push_back({line({100, 0, 0}, {100, 15, 0})});
    const auto r = graphFromTraces(makeTraces(roads, 0.5, 3, 1.0, /*passes=*/2), Config{});
    const int a = intersectionNear(r, 0, 0), b = intersectionNear(r, 200, 0);
    int h = -1;
    for (std::size_t n = 0; n < r.graph.nodes.size(); ++n)
      if (!r.node_is_end[n] && std::abs(r.graph.nodes[n].pos.x() - 100) < 5 &&
          r.graph.nodes[n].pos.y() > 12 && r.graph.nodes[n].pos.y() < 20)
        h = static_cast<int>(n);
    ASSERT_GE(a, 0) << "connected " << connected;
    ASSERT_GE(b, 0) << "connected " << connected;
    ASSERT_GE(h, 0) << "connected " << connected;
    EXPECT_EQ(r.stats.intersections, 3u) << "connected " << connected;
    EXPECT_EQ(r.stats.passed_nodes, connected ? 1u : 0u);
    EXPECT_EQ(hasEdge(r.graph, a, h), connected);
    EXPECT_EQ(hasEdge(r.graph, h, b), connected);
    EXPECT_EQ(hasEdge(r.graph, b, h), connected);
    EXPECT_EQ(hasEdge(r.graph, a, b), !connected);
  }
}

TEST(GraphBuilder, StreetFromADeadEndPastAJunctionWhoseNodeLiesOffItIsSplitThere) {
  // As above, but the main road ends 300 m east of H without a junction (the survey's border):
  // its cluster reaches only two nodes, A and H, and its east end is a dead end. That end is a
  // branch of its own, so the road is split at H (A-H, H-dead end) instead of joining A to the
  // dead end past H; without the connector it stays one street A-dead end. The street A-H is the
  // 100 m between them, not the half of the road nearer to A than to the dead end. H's arms
  // north and north-east, one cluster forking near H between two dead ends, end at H either way.
  for (const bool connected : {true, false}) {
    std::vector<Road> roads = {{line({-100, 0, 0}, {400, 0, 0})},
                               {line({0, -100, 0}, {0, 100, 0})},
                               {line({100, 15, 0}, {100, 150, 0})},
                               {line({100, 15, 0}, {170, 99, 0})},
                               {line({100, 15, 0}, {30, 99, 0})}};
    if (connected) roads.push_back({line({100, 0, 0}, {100, 15, 0})});
    const auto r = graphFromTraces(makeTraces(roads, 0.5, 3, 1.0, /*passes=*/2), Config{});
    const int a = intersectionNear(r, 0, 0);
    int h = -1, d = -1, north = -1, north_east = -1;
    for (std::size_t n = 0; n < r.graph.nodes.size(); ++n) {
      const Point3& p = r.graph.nodes[n].pos;
      const int id = static_cast<int>(n);
      if (!r.node_is_end[n] && std::abs(p.x() - 100) < 5 && p.y() > 12 && p.y() < 20) h = id;
      if (!r.node_is_end[n]) continue;
      if (std::hypot(p.x() - 400, p.y()) < 10) d = id;
      if (std::hypot(p.x() - 100, p.y() - 150) < 10) north = id;
      if (std::hypot(p.x() - 170, p.y() - 99) < 10) north_east = id;
    }
    ASSERT_GE(a, 0) << "connected " << connected;
    ASSERT_GE(h, 0) << "connected " << connected;
    ASSERT_GE(d, 0) << "connected " << connected;
    EXPECT_EQ(r.stats.intersections, 2u) << "connected " << connected;
    EXPECT_TRUE(hasEdge(r.graph, h, north)) << "connected " << connected;
    EXPECT_TRUE(hasEdge(r.graph, h, north_east)) << "connected " << connected;
    EXPECT_FALSE(hasEdge(r.graph, north, north_east)) << "connected " << connected;
    EXPECT_EQ(hasEdge(r.graph, a, h), connected);
    EXPECT_EQ(hasEdge(r.graph, h, d), connected);
    EXPECT_EQ(hasEdge(r.graph, d, h), connected);
    EXPECT_EQ(hasEdge(r.graph, a, d), !connected);
    for (const auto& e : r.graph.edges) {
      if (!connected) continue;
      if (e.u == a && e.v == h) EXPECT_NEAR(e.length_m, 110.0, 15.0);  // 100 m, then 15 m to H
      if (e.u == h && e.v == d) EXPECT_NEAR(e.length_m, 310.0, 15.0);
    }
  }
}

TEST(GraphBuilder, OverpassStreetPassesUnderTheBridge) {
  Polyline bridge;
  for (double y = -200; y <= 200; y += 5) {
    const double a = std::abs(y);
    bridge.emplace_back(0, y, a <= 40 ? 7.0 : (a >= 100 ? 0.0 : 7.0 * (100 - a) / 60.0));
  }
  const std::vector<Road> roads = {
      {line({-150, 0, 0}, {250, 0, 0})}, {bridge}, {line({120, -100, 0}, {120, 100, 0})}};
  const auto r = graphFromTraces(makeTraces(roads, 0.5, 5), Config{});
  EXPECT_EQ(r.stats.intersections, 1u);
  // Bridge (isolated, 2 dead ends), west street to the junction (1 dead end), 3 other arms.
  EXPECT_EQ(r.stats.dead_ends, 2u + 1u + 3u);
  EXPECT_EQ(countStreets(r.graph), 5u);
}

TEST(GraphBuilder, SameInputSameGraph) {
  const auto tr = makeTraces(gridRoads(3, 100, 50), 1.0, 5);
  const auto a = graphFromTraces(tr, Config{});
  const auto b = graphFromTraces(tr, Config{});
  ASSERT_EQ(a.graph.edges.size(), b.graph.edges.size());
  for (std::size_t k = 0; k < a.graph.edges.size(); ++k) {
    EXPECT_EQ(a.graph.edges[k].u, b.graph.edges[k].u);
    EXPECT_EQ(a.graph.edges[k].polyline, b.graph.edges[k].polyline);
  }
}

TEST(GraphBuilder, BadTracesThrowClearly) {
  Traces empty;
  empty.source = "empty.csv";
  try {
    graphFromTraces(empty, Config{});
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("empty"), std::string::npos) << e.what();
  }
  Traces one = makeTraces({{line({0, 0, 0}, {0.5, 0, 0}), false}});
  ASSERT_EQ(one.points.size(), 1u);
  EXPECT_THROW(graphFromTraces(one, Config{}), std::invalid_argument);
  Traces nan = makeTraces(plusRoads());
  nan.points[10].pos.y() = std::numeric_limits<double>::quiet_NaN();
  try {
    graphFromTraces(nan, Config{});
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("NaN"), std::string::npos) << e.what();
  }
  // A single straight street has no intersection.
  try {
    graphFromTraces(makeTraces({{line({0, 0, 0}, {300, 0, 0})}}), Config{});
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("no intersection"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace slamroute::roadgraph
