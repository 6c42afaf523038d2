// Motion compensation of a spinning LiDAR's sweep (evaluate/src/slam/FrontEnd deskewed): points
// fired while the vehicle moves land where they belong in the frame of the sweep's start.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "slam/FrontEnd.hpp"

namespace slamroute::evaluate {
namespace {

/// Points of a wall at x = 10 (world = frame at t) seen by a sensor that moves forward at v m/s
/// and turns at w rad/s, point k fired at k / n * 0.1 s, in the sensor frame of its firing time.
Scan movingWallScan(double v, double w, int n = 200) {
  Scan s;
  s.t = 3.0;
  s.has_point_times = true;
  for (int k = 0; k < n; ++k) {
    const double dt = 0.1 * k / n;
    const double yaw = w * dt;
    // Sensor pose at dt (constant speed along the arc, small angles: exact for w = 0).
    Pose3 T = Pose3::Identity();
    T.linear() = Eigen::AngleAxisd(yaw, Vec3::UnitZ()).toRotationMatrix();
    T.translation() =
        w == 0 ? Vec3(v * dt, 0, 0) : Vec3(v / w * std::sin(yaw), v / w * (1 - std::cos(yaw)), 0);
    const Vec3 world(10.0, -5.0 + 10.0 * k / n, 0.5 + 0.01 * k);
    const Vec3 local = T.inverse() * world;
    ScanPoint p;
    p.x = static_cast<float>(local.x());
    p.y = static_cast<float>(local.y());
    p.z = static_cast<float>(local.z());
    p.dt = static_cast<float>(dt);
    s.points.push_back(p);
  }
  return s;
}

Pose3 sweepMotion(double v, double w) {
  Pose3 M = Pose3::Identity();
  const double yaw = w * 0.1;
  M.linear() = Eigen::AngleAxisd(yaw, Vec3::UnitZ()).toRotationMatrix();
  M.translation() =
      w == 0 ? Vec3(v * 0.1, 0, 0) : Vec3(v / w * std::sin(yaw), v / w * (1 - std::cos(yaw)), 0);
  return M;
}

double worstWallError(const Scan& s) {
  double worst = 0;
  for (const auto& p : s.points) worst = std::max(worst, std::abs(p.x - 10.0));
  return worst;
}

TEST(Deskew, DrivingStraightTheWallIsFlatAgain) {
  const Scan raw = movingWallScan(15.0, 0.0);
  EXPECT_GT(worstWallError(raw), 1.4);  // 15 m/s over 0.1 s: 1.5 m of smear
  const Scan fixed = slam::deskewed(raw, sweepMotion(15.0, 0.0), 0.1);
  EXPECT_LT(worstWallError(fixed), 1e-4);
  EXPECT_FALSE(fixed.has_point_times);
  EXPECT_EQ(fixed.t, raw.t);
}

TEST(Deskew, TurningTheWallIsFlatAgain) {
  const double w = 60.0 * std::numbers::pi / 180.0;  // 60 deg/s
  const Scan raw = movingWallScan(8.0, w);
  EXPECT_GT(worstWallError(raw), 0.3);
  const Scan fixed = slam::deskewed(raw, sweepMotion(8.0, w), 0.1);
  EXPECT_LT(worstWallError(fixed), 1e-3);
}

TEST(Deskew, AScanWithoutPointTimesIsLeftAlone) {
  Scan raw = movingWallScan(15.0, 0.0);
  raw.has_point_times = false;
  const Scan same = slam::deskewed(raw, sweepMotion(15.0, 0.0), 0.1);
  ASSERT_EQ(same.points.size(), raw.points.size());
  for (std::size_t i = 0; i < raw.points.size(); ++i) EXPECT_EQ(same.points[i].x, raw.points[i].x);
}

// Without odometry the sweep is deskewed again with the step that ends at its first registration:
// a step of 3 m straight ahead over 0.2 s is 1.5 m over the 0.1 s sweep, wherever and however
// turned the step lies in the world.
TEST(Deskew, TheStepToTheSweepGivesItsMotion) {
  Pose3 from = Pose3::Identity();
  from.linear() = Eigen::AngleAxisd(0.5, Vec3::UnitZ()).toRotationMatrix();
  from.translation() = Vec3(40.0, -7.0, 1.2);
  Pose3 ahead = Pose3::Identity();
  ahead.translation() = Vec3(3.0, 0, 0);
  const Pose3 sweep = slam::sweepMotionOfStep(from, from * ahead, 0.2, 0.1);
  EXPECT_NEAR(sweep.translation().x(), 1.5, 1e-9);
  EXPECT_NEAR(sweep.translation().tail<2>().norm(), 0.0, 1e-9);

  const Scan fixed = slam::deskewed(movingWallScan(15.0, 0.0), sweep, 0.1);
  EXPECT_LT(worstWallError(fixed), 1e-4);
  EXPECT_THROW(slam::sweepMotionOfStep(from, from * ahead, 0.0, 0.1), std::invalid_argument);
}

}  // namespace
}  // namespace slamroute::evaluate
