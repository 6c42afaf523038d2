// A SUMO-style U-turn: the car slows down and turns 180 deg in 2 s (90 deg/s, 18 deg between scans
// at the default stride of 2). runSlam must take every scan while turning and keep the heading.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include "SyntheticScene.hpp"
#include "slamroute/core/Yaw.hpp"
#include "slamroute/evaluate/Metrics.hpp"
#include "slamroute/evaluate/Slam.hpp"

namespace slamroute::evaluate {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

/// 10 Hz: 2 s straight at 3 m/s, a 2 s U-turn of radius 1.5 m (2.4 m/s), 2 s straight back.
class UTurnSource : public ScanSource {
 public:
  explicit UTurnSource(test::Scene scene = test::cityScene(100.0)) : scene_(std::move(scene)) {
    spec_.channels = 32;
    spec_.horizontal_samples = 900;
  }
  std::size_t size() const override { return 60; }
  double time(std::size_t i) const override { return 0.1 * static_cast<double>(i); }
  static Pose3 pose(std::size_t i) {
    const double t = 0.1 * static_cast<double>(i);
    const double x0 = -8.0, v = 3.0, r = 1.5;
    if (t <= 2.0) return test::poseXYZYaw(x0 + v * t, 0.0, 1.8, 0.0);
    if (t <= 4.0) {
      const double a = (t - 2.0) / 2.0 * std::numbers::pi;  // 0 .. 180 deg
      return test::poseXYZYaw(x0 + 2 * v + r * std::sin(a), r - r * std::cos(a), 1.8, a);
    }
    return test::poseXYZYaw(x0 + 2 * v - v * (t - 4.0), 2 * r, 1.8, std::numbers::pi);
  }
  Scan scan(std::size_t i) const override {
    return test::scanScene(scene_, pose(i), spec_, time(i), 0.02, 7 + i);
  }
  LidarSpec spec() const override { return spec_; }

 private:
  test::Scene scene_;
  LidarSpec spec_;
};

double finalYawErrorDeg(const SlamResult& r) {
  const Pose3 err = UTurnSource::pose(59).inverse() * r.trajectory.back().T_world_body;
  return Eigen::AngleAxisd(err.rotation()).angle() / kDeg;
}

TEST(Turn, FixedStrideTakesHalfTheScans) {
  const UTurnSource src;
  Config cfg;
  cfg.loop.enabled = false;
  cfg.input.dense_turn_rate_deg_s = 0;  // off
  cfg.input.dense_after_failure_s = 0;
  const SlamResult r = runSlam(src, cfg, UTurnSource::pose(0), {},
                               UTurnSource::pose(0).inverse() * UTurnSource::pose(1));
  EXPECT_EQ(r.trajectory.size(), 30u);
}

/// Wheel odometry + gyro of the U-turn (exact): speed and yaw rate of each 0.1 s interval.
WheelOdometry uTurnOdometry() {
  std::vector<OdometrySample> s;
  for (std::size_t i = 0; i + 1 < 60; ++i) {
    const Pose3 d = UTurnSource::pose(i).inverse() * UTurnSource::pose(i + 1);
    s.push_back({0.1 * static_cast<double>(i), d.translation().norm() / 0.1, yawOf(d) / 0.1});
  }
  return WheelOdometry(std::move(s));
}

/// How the U-turn is run: with or without the wheel odometry + gyro, and whether the config lets
/// the SLAM use it.
struct OdometryCase {
  std::string name;
  bool give_odometry;
  bool use_wheel_odometry;
  bool turnsWithTheCar() const { return give_odometry && use_wheel_odometry; }
};

SlamResult runUTurn(const UTurnSource& src, const OdometryCase& c) {
  Config cfg;
  cfg.loop.enabled = false;
  cfg.odometry.use_wheel_odometry = c.use_wheel_odometry;
  const WheelOdometry odo = uTurnOdometry();
  const Pose3 T0 = UTurnSource::pose(0), V0 = T0.inverse() * UTurnSource::pose(1);
  return runSlam(src, cfg, T0, {}, V0, c.give_odometry ? &odo : nullptr);
}

std::string caseName(const ::testing::TestParamInfo<OdometryCase>& info) { return info.param.name; }

const OdometryCase kLidarOnly{"LidarOnly", false, true};
const OdometryCase kWithOdometry{"WithOdometry", true, true};
const OdometryCase kOdometryIgnored{"OdometryIgnored", true, false};

// In a street with features the odometry only seeds the registration: with it or without, every
// scan of the turn is used and the heading and position stay right.
class UTurnInTheCity : public ::testing::TestWithParam<OdometryCase> {};

TEST_P(UTurnInTheCity, TakesEveryScanOfTheTurnAndKeepsTheHeading) {
  const SlamResult r = runUTurn(UTurnSource(), GetParam());
  // Every scan of the turn (t = 2.1 ... 4.0) is used; fewer than all 60 overall.
  int in_turn = 0;
  for (const auto& p : r.trajectory) in_turn += p.t > 2.05 && p.t < 4.05;
  EXPECT_EQ(in_turn, 20);
  EXPECT_LT(r.trajectory.size(), 58u);
  EXPECT_LT(finalYawErrorDeg(r), 1.0);
  const Vec3 d =
      r.trajectory.back().T_world_body.translation() - UTurnSource::pose(59).translation();
  EXPECT_LT(d.norm(), 0.3) << d.transpose();
}

INSTANTIATE_TEST_SUITE_P(Turn, UTurnInTheCity, ::testing::Values(kLidarOnly, kWithOdometry),
                         caseName);

// An open field: the LiDAR sees only the flat ground, which fixes height, roll and pitch but
// nothing of x, y and yaw. Without odometry (or with use_wheel_odometry: false) the estimate
// drives on straight through the U-turn; with the wheel odometry + gyro it turns with the car.
class UTurnInAnOpenField : public ::testing::TestWithParam<OdometryCase> {};

TEST_P(UTurnInAnOpenField, TurnsOnlyWithTheWheelOdometry) {
  const SlamResult r = runUTurn(UTurnSource(test::Scene{}), GetParam());
  if (!GetParam().turnsWithTheCar()) {
    EXPECT_GT(finalYawErrorDeg(r), 90.0);
    return;
  }
  EXPECT_LT(finalYawErrorDeg(r), 1.0);
  const auto& last = r.trajectory.back();  // scan 58 or 59 (stride 2 on the straight)
  const Vec3 d =
      last.T_world_body.translation() -
      UTurnSource::pose(static_cast<std::size_t>(std::lround(last.t / 0.1))).translation();
  EXPECT_LT(d.norm(), 0.2) << d.transpose();
}

INSTANTIATE_TEST_SUITE_P(Turn, UTurnInAnOpenField,
                         ::testing::Values(kLidarOnly, kWithOdometry, kOdometryIgnored), caseName);

}  // namespace
}  // namespace slamroute::evaluate
