// Street polylines (roadgraph/src/Centreline.cpp): spikes left by bins of points reached the long
// way round are dropped; real bends and the ends stay. A street's centreline follows the way
// between its ends when one arm's lanes join the rest only at a corner (StreetClusters.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "StreetsOf.hpp"

namespace slamroute::roadgraph::detail {
namespace {

double length2d(const Polyline& pl) {
  double s = 0.0;
  for (std::size_t i = 0; i + 1 < pl.size(); ++i) s += (pl[i + 1] - pl[i]).head<2>().norm();
  return s;
}

Polyline straightNorth(double from_m, double to_m, double step_m) {
  Polyline pl;
  for (double y = from_m; y <= to_m + 1e-9; y += step_m) pl.emplace_back(0.0, y, 0.0);
  return pl;
}

TEST(Centreline, ASpikeToTheFarEndAndBackIsDropped) {
  // Bologna, seed 1, the street of SUMO edge 84: node, a bin beside the far end (140 m), one
  // halfway back (60 m), then the street northwards every 5 m from 45 to 145 m: 344 m for a
  // street of ~145 m.
  Polyline pl{Point3(0, 0, 0), Point3(0, 140, 0), Point3(2, 60, 0)};
  const Polyline street = straightNorth(45.0, 145.0, 5.0);
  pl.insert(pl.end(), street.begin(), street.end());
  EXPECT_NEAR(length2d(pl), 140.0 + 80.0 + 15.1 + 100.0, 0.5);
  dropSpikes(pl, 10.0);
  EXPECT_NEAR(length2d(pl), 145.0, 1e-9);  // node, then the street
  EXPECT_EQ(pl.front(), Point3(0, 0, 0));
  EXPECT_EQ(pl.size(), street.size() + 1);
}

TEST(Centreline, BendsHairpinsAndShortJitterStay) {
  Polyline right_angle = straightNorth(0.0, 50.0, 5.0);
  for (double x = 5.0; x <= 50.0; x += 5.0) right_angle.emplace_back(x, 50.0, 0.0);
  Polyline hairpin = straightNorth(0.0, 50.0, 5.0);  // turns back over three vertices
  for (const Point3& p : {Point3(3, 54, 0), Point3(7, 54, 0), Point3(10, 50, 0)})
    hairpin.push_back(p);
  for (double y = 45.0; y >= 0.0; y -= 5.0) hairpin.emplace_back(10.0, y, 0.0);
  // GPS jitter: 3 m back and forth within the street, legs shorter than two steps.
  Polyline jitter{Point3(0, 0, 0), Point3(0, 8, 0), Point3(0, 5, 0), Point3(0, 20, 0)};
  for (Polyline pl : {right_angle, hairpin, jitter}) {
    const Polyline before = pl;
    dropSpikes(pl, 10.0);
    EXPECT_EQ(pl, before);
  }
}

/// The default city's street R1C2 - R0C2 - T2 on survey seeds 2 and 4: an L whose north-south
/// arm has its two one-way lanes 13 m apart, joined to the east-west arm (3.2 m between its lanes,
/// one cluster) only at the corner K (0, 0). Nodes A (0, 212) at the top and B (312, 0) at the
/// east end. The southbound lane reaches 20 m closer to A, so the street runs from its top to
/// the east end; the northbound lane is reached from there through the corner, and its points lie
/// 200-400 m along the geodesic order, the same as the east arm's first 200 m. (The traces of
/// the road from the east end come first: the geodesic ends are searched from their first point.)
std::vector<testing::Road> cornerWithSplitLanes() {
  return {{{Point3(300, 0, 0), Point3(5, 0, 0), Point3(5, 190, 0)}, false},     // west, north
          {{Point3(-5, 210, 0), Point3(-5, 0, 0), Point3(300, 0, 0)}, false}};  // south, east
}

/// How far the centreline strays from the L (x = 0 north of the corner, y = 0 east of it).
double offTheL(const Polyline& centre) {
  double far = 0.0;
  for (const auto& p : centre)
    far = std::max(far, std::min(std::hypot(p.x(), std::max(0.0, -p.y())),
                                 std::hypot(std::max(0.0, -p.x()), p.y())));
  return far;
}

TEST(Centreline, ArmWhoseLanesJoinOnlyAtTheCornerLeavesTheOtherLaneOut) {
  const auto b = testing::streetsOf(cornerWithSplitLanes(), {Point3(0, 212, 0), Point3(312, 0, 0)});
  const Street* s = testing::streetBetween(b, 0, 1);
  ASSERT_NE(s, nullptr);
  EXPECT_NEAR(polylineLength(s->centre), 500.0, 15.0);  // about 200 m south, 300 m east
  EXPECT_LT(offTheL(s->centre), 8.0);
  // With the rule off, the other lane's points share bins with the east arm's and pull the
  // centreline across the block.
  EdgeConfig all;
  all.centreline_branch_max_m = 1e5;
  const auto mixed =
      testing::streetsOf(cornerWithSplitLanes(), {Point3(0, 212, 0), Point3(312, 0, 0)}, all);
  const Street* m = testing::streetBetween(mixed, 0, 1);
  ASSERT_NE(m, nullptr);
  EXPECT_GT(offTheL(m->centre), 30.0);
}

}  // namespace
}  // namespace slamroute::roadgraph::detail
