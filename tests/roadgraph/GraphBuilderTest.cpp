// Streets, dead ends and directions of travel (paper §3.1 steps 2-3) on synthetic traces.
#include <gtest/gtest.h>

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
  const auto r = buildRoadGraph(makeTraces(plusRoads()), Config{});
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
  const auto r = buildRoadGraph(makeTraces(gridRoads(3, 100, 0)), Config{});
  EXPECT_EQ(r.stats.intersections, 5u);
  EXPECT_EQ(r.stats.dead_ends, 0u);
  EXPECT_EQ(countStreets(r.graph), 8u);
  double ring = 0;
  for (const auto& e : r.graph.edges)
    if (e.length_m > 150) ring += e.length_m;
  EXPECT_NEAR(ring, 8 * 200.0, 8 * 8.0);  // 4 ring streets x 2 directions, 200 m each
}

TEST(GraphBuilder, GridWithOverhangHasNineIntersectionsAndTwelveDeadEnds) {
  const auto r = buildRoadGraph(makeTraces(gridRoads(3, 100, 50), 1.0, 11), Config{});
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
  const auto r = buildRoadGraph(makeTraces(roads, 0.5, 3), Config{});
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
  const auto r = buildRoadGraph(makeTraces(roads, 0.5, 3), Config{});
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
  const auto r = buildRoadGraph(tr, Config{});
  EXPECT_EQ(r.stats.merged_end_pairs, 1u);
  EXPECT_EQ(r.stats.dead_ends, 5u);  // west, south, north, top of the north street, corner
  EXPECT_EQ(countStreets(r.graph), 5u);
  int corner = -1;
  for (std::size_t n = 0; n < r.graph.nodes.size(); ++n) {
    int deg = 0;
    for (const auto& e : r.graph.edges) deg += (e.u == static_cast<int>(n)) + (e.v == static_cast<int>(n));
    if (r.node_is_end[n] && deg == 4) corner = static_cast<int>(n);
  }
  ASSERT_GE(corner, 0) << "the corner node joins two two-way streets";
  EXPECT_NEAR(r.graph.nodes[static_cast<std::size_t>(corner)].pos.x(), 104.0, 5.0);
  EXPECT_NEAR(r.graph.nodes[static_cast<std::size_t>(corner)].pos.y(), 5.0, 5.0);

  Config off;
  off.edges.end_merge_m = 0.0;
  const auto apart = buildRoadGraph(tr, off);
  EXPECT_EQ(apart.stats.merged_end_pairs, 0u);
  EXPECT_EQ(apart.stats.dead_ends, 6u);
}

TEST(GraphBuilder, OverpassStreetPassesUnderTheBridge) {
  Polyline bridge;
  for (double y = -200; y <= 200; y += 5) {
    const double a = std::abs(y);
    bridge.emplace_back(0, y, a <= 40 ? 7.0 : (a >= 100 ? 0.0 : 7.0 * (100 - a) / 60.0));
  }
  const std::vector<Road> roads = {{line({-150, 0, 0}, {250, 0, 0})},
                                   {bridge},
                                   {line({120, -100, 0}, {120, 100, 0})}};
  const auto r = buildRoadGraph(makeTraces(roads, 0.5, 5), Config{});
  EXPECT_EQ(r.stats.intersections, 1u);
  // Bridge (isolated, 2 dead ends), west street to the junction (1 dead end), 3 other arms.
  EXPECT_EQ(r.stats.dead_ends, 2u + 1u + 3u);
  EXPECT_EQ(countStreets(r.graph), 5u);
}

TEST(GraphBuilder, SameInputSameGraph) {
  const auto tr = makeTraces(gridRoads(3, 100, 50), 1.0, 5);
  const auto a = buildRoadGraph(tr, Config{});
  const auto b = buildRoadGraph(tr, Config{});
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
    buildRoadGraph(empty, Config{});
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("empty"), std::string::npos) << e.what();
  }
  Traces one = makeTraces({{line({0, 0, 0}, {0.5, 0, 0}), false}});
  ASSERT_EQ(one.points.size(), 1u);
  EXPECT_THROW(buildRoadGraph(one, Config{}), std::invalid_argument);
  Traces nan = makeTraces(plusRoads());
  nan.points[10].pos.y() = std::numeric_limits<double>::quiet_NaN();
  try {
    buildRoadGraph(nan, Config{});
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("NaN"), std::string::npos) << e.what();
  }
  // A single straight street has no intersection.
  try {
    buildRoadGraph(makeTraces({{line({0, 0, 0}, {300, 0, 0})}}), Config{});
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("no intersection"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace slamroute::roadgraph
