// Junctions that few vehicles show (paper §3.1 step 1 on sparse traces): a side arm driven by one
// or two vehicles off a well-driven street, or one whose vehicles stop short of the street (their
// routes end at the stop line), is still a T junction with three streets.
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

/// Main street (-250, 0) - (250, 0) and two crossing streets at x = -150 and 150, each driven
/// both ways by five vehicles, plus the side arm's vehicles: the T's arm runs south from (0, 0).
/// The busy crossings set the median a junction's votes are judged against.
Traces teeTraces(const std::vector<Road>& side) {
  Traces tr = makeTraces({{line({-250, 0, 0}, {250, 0, 0})},
                          {line({-150, -100, 0}, {-150, 100, 0})},
                          {line({150, -100, 0}, {150, 100, 0})}},
                         0.5, 3, 1.0, /*passes=*/5);
  const Traces arm = makeTraces(side, 0.5, 5);
  const int base = static_cast<int>(tr.vehicles.size());
  for (const auto& v : arm.vehicles) tr.vehicles.push_back("side_" + v);
  for (auto p : arm.points) {
    p.vehicle += base;
    p.t += 1000.0;
    tr.points.push_back(p);
  }
  return tr;
}

struct Tee {
  std::size_t intersections = 0;
  int centre = -1;  ///< the intersection node within 10 m of (0, 0)
  std::size_t streets_at_centre = 0;
  std::size_t streets = 0;
};

Tee describe(const GraphBuildResult& r) {
  Tee t;
  for (std::size_t n = 0; n < r.graph.nodes.size(); ++n) {
    if (r.node_is_end[n]) continue;
    ++t.intersections;
    if (r.graph.nodes[n].pos.head<2>().norm() < 10.0) t.centre = static_cast<int>(n);
  }
  std::set<int> all, at_centre;
  for (const auto& e : r.graph.edges) {
    all.insert(e.street);
    if (e.u == t.centre || e.v == t.centre) at_centre.insert(e.street);
  }
  t.streets = all.size();
  t.streets_at_centre = at_centre.size();
  return t;
}

/// The two crossings, the T, and nine streets: the main street in four (dead end, crossing, T,
/// crossing, dead end), the crossing streets' four arms and the side arm.
void expectTee(const GraphBuildResult& r) {
  const Tee t = describe(r);
  EXPECT_EQ(t.intersections, 3u);
  ASSERT_GE(t.centre, 0) << "no junction node at the T";
  EXPECT_EQ(t.streets_at_centre, 3u);
  EXPECT_EQ(t.streets, 9u);
}

TEST(SparseJunctions, SideArmDrivenByOneVehicleIsAJunction) {
  // One vehicle comes along the main street from the west and turns south.
  const std::vector<Road> side = {{{{-250, 0, 0}, {0, 0, 0}, {0, -150, 0}}, /*two_way=*/false}};
  const auto r = graphFromTraces(teeTraces(side), Config{});
  expectTee(r);
  EXPECT_EQ(r.stats.stop_line_junctions, 0u) << "the hollow cylinder finds this one";
}

TEST(SparseJunctions, SideArmWhoseVehiclesStopShortOfTheStreetIsAJunction) {
  // Two vehicles drive north on the side arm and their routes end at its stop line, 6-7 m short
  // of the main street's near lane (y = -1.6): their traces never reach it.
  const std::vector<Road> side = {{line({0, -150, 0}, {0, -8, 0}), /*two_way=*/false},
                                  {line({0, -150, 0}, {0, -9, 0}), /*two_way=*/false}};
  const Traces tr = teeTraces(side);
  const auto r = graphFromTraces(tr, Config{});
  expectTee(r);
  EXPECT_EQ(r.stats.stop_line_junctions, 1u);
  Config off;
  off.edges.stop_line_reach_m = 0.0;
  const Tee apart = describe(graphFromTraces(tr, off));
  EXPECT_LT(apart.centre, 0) << "without the rule the arm dead-ends beside the street";
  EXPECT_EQ(apart.intersections, 2u);
}

}  // namespace
}  // namespace slamroute::roadgraph
