// Street polylines (roadgraph/src/Centreline.cpp): spikes left by bins of points reached the long
// way round are dropped; real bends and the ends stay.
#include <gtest/gtest.h>

#include "Streets.hpp"

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

}  // namespace
}  // namespace slamroute::roadgraph::detail
