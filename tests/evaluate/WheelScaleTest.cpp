// The wheel scale measured by the LiDAR (evaluate/src/slam/WheelScale): known ratios per stretch,
// an outlier stretch, the warm-up and the bound.
#include <gtest/gtest.h>

#include "slam/WheelScale.hpp"

namespace slamroute::evaluate {
namespace {

OdometryConfig scaleConfig() {
  OdometryConfig c;
  c.wheel_scale_stretch_m = 50.0;
  c.wheel_scale_stretches = 5;
  c.wheel_scale_min_stretches = 3;
  c.wheel_scale_max = 0.05;
  return c;
}

/// Steps of 2 m by the wheels over `metres`, the registration measuring `ratio` of each.
void drive(slam::WheelScale& s, double metres, double ratio) {
  for (double d = 0; d < metres - 1e-9; d += 2.0) s.observe(2.0, 2.0 * ratio);
}

TEST(WheelScale, IsTheRatioOfRegisteredToWheelDistance) {
  const OdometryConfig c = scaleConfig();
  slam::WheelScale s(c);
  drive(s, 100.0, 0.98);  // two stretches: not enough yet
  EXPECT_EQ(s.scale(), 1.0);
  drive(s, 50.0, 0.98);
  EXPECT_NEAR(s.scale(), 0.98, 1e-12);
}

TEST(WheelScale, AStretchWhereTheRegistrationSlidIsAnOutlier) {
  const OdometryConfig c = scaleConfig();
  slam::WheelScale s(c);
  drive(s, 150.0, 1.01);
  drive(s, 50.0, 0.94);  // a bridge: the LiDAR saw the car move 6 % less
  EXPECT_NEAR(s.scale(), 1.01, 1e-12);
  drive(s, 50.0, 1.01);
  EXPECT_NEAR(s.scale(), 1.01, 1e-12);
}

TEST(WheelScale, FollowsAChangeOnceMostRecentStretchesAgree) {
  const OdometryConfig c = scaleConfig();
  slam::WheelScale s(c);
  drive(s, 250.0, 1.0);
  drive(s, 150.0, 0.97);  // three of the last five stretches
  EXPECT_NEAR(s.scale(), 0.97, 1e-12);
}

TEST(WheelScale, StaysWithinItsBoundAndOffWithoutAStretch) {
  OdometryConfig c = scaleConfig();
  slam::WheelScale bounded(c);
  drive(bounded, 250.0, 0.5);
  EXPECT_NEAR(bounded.scale(), 0.95, 1e-12);
  c.wheel_scale_stretch_m = 0.0;
  slam::WheelScale off(c);
  drive(off, 250.0, 0.98);
  EXPECT_EQ(off.scale(), 1.0);
}

}  // namespace
}  // namespace slamroute::evaluate
