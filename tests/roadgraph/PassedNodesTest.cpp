// Streets that run through a junction whose node lies off them (PassedNodes.cpp), on hand-made
// traces with the nodes given: the street step alone (clearing, clusters, attachment), so the
// known answer does not depend on where the hollow cylinder votes.
//
// The junction: arms west, east and south meet at K (0, 0); its node H lies 14 m north of K
// (a big junction's vote, Bologna junction 9), beyond which a street goes on north. The west and
// east arms end 12 m before nodes A (-162, 0) and B (162, 0); the south arm ends at (0, -200)
// with no node (the map border). The cluster of the three arms reaches A, B and H.
#include <gtest/gtest.h>

#include <cmath>

#include "StreetsOf.hpp"

namespace slamroute::roadgraph {
namespace {

using testing::line;
using testing::makeTraces;
using testing::Road;

using Built = testing::BuiltStreets;
using testing::streetBetween;
using testing::streetsOf;

const std::vector<Point3> kABH = {Point3(-162, 0, 0), Point3(162, 0, 0), Point3(0, 14, 0)};

/// A street with a dead end within 10 m of p, or nullptr.
const detail::Street* streetFromDeadEndNear(const Built& b, const Point3& p) {
  for (const auto& s : b.streets)
    for (const int end : {s.u, s.v})
      if (b.nodes.is_end[static_cast<std::size_t>(end)] &&
          (b.nodes.pos[static_cast<std::size_t>(end)] - p).norm() < 10.0)
        return &s;
  return nullptr;
}

/// The farthest a centreline point lies from the line y = 0, outside the junction (16 m around
/// K: the cleared radius and a clustering step, where the arms' points meet).
double offTheMainRoad(const detail::Street& s) {
  double far = 0.0;
  for (const auto& p : s.centre)
    if (p.head<2>().norm() > 16.0) far = std::max(far, std::abs(p.y()));
  return far;
}

std::vector<Road> threeArms() {
  return {{line({-150, 0, 0}, {150, 0, 0})},   // west and east arms through K
          {line({0, -200, 0}, {0, 150, 0})}};  // south arm, through K and H on north
}

TEST(PassedNodes, DeadEndArmIsABranchOfItsOwn) {
  // Its points go to its own street, dead end -> H, not to the west or east arm's street, whose
  // centreline would then run from A to K and on down the south arm.
  const Built b = streetsOf(threeArms(), kABH);
  const detail::Street* west = streetBetween(b, 0, 2);
  const detail::Street* east = streetBetween(b, 1, 2);
  ASSERT_NE(west, nullptr);
  ASSERT_NE(east, nullptr);
  EXPECT_LT(offTheMainRoad(*west), 5.0);
  EXPECT_LT(offTheMainRoad(*east), 5.0);
  const detail::Street* south = streetFromDeadEndNear(b, Point3(0, -200, 0));
  ASSERT_NE(south, nullptr);
  EXPECT_TRUE(south->u == 2 || south->v == 2);  // it ends at H
  EXPECT_NEAR(polylineLength(south->centre), 200.0, 10.0);
}

TEST(PassedNodes, CarriagewayThatJoinsOnlyThroughTheJunctionStaysOnItsArm) {
  // The south arm is divided and ends at node S (0, -212): its carriageways (one-way, 10 m
  // apart, too far for one cluster) are joined to the cluster only at K, and the northbound one
  // ends 60 m short of S. Its points lie past K on every branch's geodesic path (the others'
  // through K); it runs beside the south arm, so it belongs to the street S -> H, not to the
  // west arm's street (which would run from A to K and down it).
  const std::vector<Road> roads = {{line({-150, 0, 0}, {150, 0, 0})},
                                   {line({-5, 0, 0}, {-5, -200, 0}), false},
                                   {line({5, -140, 0}, {5, -2, 0}), false},
                                   {line({0, 0, 0}, {0, 150, 0})}};
  std::vector<Point3> nodes = kABH;
  nodes.emplace_back(0, -212, 0);
  const Built b = streetsOf(roads, nodes);
  const detail::Street* west = streetBetween(b, 0, 2);
  const detail::Street* east = streetBetween(b, 1, 2);
  const detail::Street* south = streetBetween(b, 3, 2);
  ASSERT_NE(west, nullptr);
  ASSERT_NE(east, nullptr);
  ASSERT_NE(south, nullptr);
  EXPECT_LT(offTheMainRoad(*west), 5.0);
  EXPECT_LT(offTheMainRoad(*east), 5.0);
  double off_axis = 0.0;  // the south street's centreline lies between its carriageways
  for (const auto& p : south->centre) off_axis = std::max(off_axis, std::abs(p.x()));
  EXPECT_LT(off_axis, 8.0);
  EXPECT_NEAR(polylineLength(south->centre), 200.0, 15.0);
}

TEST(PassedNodes, NodeBesideWhereTheArmsMeetIsThePassedNode) {
  // The arms west (to a dead end at (-400, 0), the longest), east (to node B (262, 0)) and north
  // (to node N (0, 262)) meet at K (0, 0); the junction's node H lies 18 m off K at (-6, -17),
  // outside the reach of K's points. A one-way carriageway leaves H and joins the east arm only 80
  // m east of K: its first point is the cluster's nearest to H, so every contact lies far from the
  // branch point of the nodes. The branch point of the other contacts (K) lies within
  // attach_max_m of H: H is the passed node, and the arms are streets to it.
  const std::vector<Road> roads = {{line({-400, 0, 0}, {250, 0, 0})},
                                   {line({0, 0, 0}, {0, 250, 0})},
                                   {{Point3(-6, -150, 0), Point3(-6, -17, 0), Point3(4, -8, 0),
                                     Point3(60, -8, 0), Point3(80, -3, 0), Point3(250, -3, 0)},
                                    false}};
  const Built b = streetsOf(roads, {Point3(262, 0, 0), Point3(0, 262, 0), Point3(-6, -17, 0)});
  const detail::Street* east = streetBetween(b, 0, 2);
  const detail::Street* north = streetBetween(b, 1, 2);
  const detail::Street* west = streetFromDeadEndNear(b, Point3(-400, 0, 0));
  ASSERT_NE(east, nullptr);
  ASSERT_NE(north, nullptr);
  ASSERT_NE(west, nullptr);
  EXPECT_TRUE(west->u == 2 || west->v == 2);  // the west arm ends at H too
  EXPECT_LT(offTheMainRoad(*west), 5.0);
  EXPECT_EQ(streetBetween(b, 0, 1), nullptr);
}

}  // namespace
}  // namespace slamroute::roadgraph
