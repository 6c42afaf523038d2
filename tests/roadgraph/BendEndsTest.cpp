// A street a survey route set off on, beside a junction that the other vehicles only turn at
// (BendEnds.cpp): the junction is a node joining three streets, so the street can be entered.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "SyntheticTraces.hpp"
#include "slamroute/roadgraph/GraphBuilder.hpp"

namespace slamroute::roadgraph {
namespace {

using testing::line;
using testing::makeTraces;
using testing::Road;

/// Junction J at (0, 0), all one-way as at default city R3C3: the street from the south turns
/// west there (five vehicles); west of it a two-way crossing street at x = -150. `north`: the
/// vehicles of the street going on north from J.
Traces departTraces(const Road& north) {
  Traces tr = makeTraces({{{{0, -150, 0}, {0, 0, 0}, {-250, 0, 0}}, /*two_way=*/false},
                          {line({-150, -150, 0}, {-150, 150, 0})}},
                         0.5, 3, 1.0, /*passes=*/5);
  const Traces more = makeTraces({north}, 0.5, 5, 1.0, /*passes=*/2);
  const int base = static_cast<int>(tr.vehicles.size());
  for (const auto& v : more.vehicles) tr.vehicles.push_back("north_" + v);
  for (auto p : more.points) {
    p.vehicle += base;
    p.t += 1000.0;
    tr.points.push_back(p);
  }
  return tr;
}

/// The node within 10 m of (x, y) and the streets at it (-1, 0 when none).
std::pair<int, std::size_t> nodeNear(const GraphBuildResult& r, double x, double y) {
  for (std::size_t n = 0; n < r.graph.nodes.size(); ++n) {
    if (std::hypot(r.graph.nodes[n].pos.x() - x, r.graph.nodes[n].pos.y() - y) > 10.0) continue;
    std::set<int> streets;
    for (const auto& e : r.graph.edges)
      if (e.u == static_cast<int>(n) || e.v == static_cast<int>(n)) streets.insert(e.street);
    return {static_cast<int>(n), streets.size()};
  }
  return {-1, 0};
}

TEST(BendEnds, StreetWhoseVehiclesSetOffBesideABendStartsAtAJunctionThere) {
  // The north street's vehicles start 12 m north of J (their routes start on it): no trace
  // runs through J into it, and it lines up with the street from the south.
  const Traces tr = departTraces({line({0, 12, 0}, {0, 200, 0}), /*two_way=*/false});
  const auto r = graphFromTraces(tr, Config{});
  EXPECT_EQ(r.stats.bend_end_junctions, 1u);
  const auto [j, streets] = nodeNear(r, 0, 0);
  ASSERT_GE(j, 0) << "no node at the bend";
  EXPECT_FALSE(r.node_is_end[static_cast<std::size_t>(j)]);
  EXPECT_EQ(streets, 3u);  // south, west, and the north street
  bool north_out = false;
  for (const auto& e : r.graph.edges)
    if (e.u == j && r.graph.nodes[static_cast<std::size_t>(e.v)].pos.y() > 150.0) north_out = true;
  EXPECT_TRUE(north_out) << "the north street is entered at J";
  Config off;
  off.edges.bend_end_reach_m = 0.0;
  const auto apart = graphFromTraces(tr, off);
  EXPECT_EQ(apart.stats.bend_end_junctions, 0u);
  EXPECT_LT(nodeNear(apart, 0, 0).first, 0) << "without the rule the street starts beside J";
  EXPECT_EQ(apart.stats.dead_ends, r.stats.dead_ends + 1);
}

TEST(BendEnds, StreetSetOffBesideAStraightStreetStaysADeadEnd) {
  // The same start beside a street that runs straight on (no bend): nothing lines up.
  Traces tr = makeTraces({{line({0, -150, 0}, {0, 250, 0})}, {line({-150, 150, 0}, {150, 150, 0})}},
                         0.5, 3, 1.0, /*passes=*/5);
  const Traces more = makeTraces({{line({12, 8, 0}, {12, 100, 0}), false}}, 0.5, 5, 1.0, 2);
  const int base = static_cast<int>(tr.vehicles.size());
  for (const auto& v : more.vehicles) tr.vehicles.push_back("side_" + v);
  for (auto p : more.points) {
    p.vehicle += base;
    p.t += 1000.0;
    tr.points.push_back(p);
  }
  const auto r = graphFromTraces(tr, Config{});
  EXPECT_EQ(r.stats.bend_end_junctions, 0u);
}

}  // namespace
}  // namespace slamroute::roadgraph
