// The bounds a registration must stay within before the SLAM believes it.
#include <gtest/gtest.h>

#include <numbers>

#include "slamroute/evaluate/MotionChecks.hpp"

namespace slamroute::evaluate {
namespace {

Pose3 pose(double x, double y, double yaw_deg) {
  Pose3 T = Pose3::Identity();
  T.linear() =
      Eigen::AngleAxisd(yaw_deg * std::numbers::pi / 180.0, Vec3::UnitZ()).toRotationMatrix();
  T.translation() = Vec3(x, y, 0.0);
  return T;
}

TEST(MotionChecks, TurnRateFallsWithSpeed) {
  const Config cfg;  // 6 m/s^2 lateral, cap 10 deg per 0.1 s
  EXPECT_NEAR(maxTurnRate(cfg, 12.0), 0.5, 1e-12);
  EXPECT_NEAR(maxTurnRate(cfg, 0.0), 10.0 * std::numbers::pi / 180.0 / 0.1, 1e-12);  // capped
}

TEST(MotionChecks, ScaledMotionHalvesAngleAndTranslation) {
  const Pose3 h = scaledMotion(pose(2.0, 1.0, 20.0), 0.5);
  EXPECT_NEAR(rotationAngle(h) * 180.0 / std::numbers::pi, 10.0, 1e-9);
  EXPECT_NEAR(h.translation().x(), 1.0, 1e-12);
}

TEST(MotionChecks, HeadingJumpBeyondWhatACarCanTurnIsImplausible) {
  const Config cfg;
  const Pose3 pred = pose(100, 50, 30);
  // At 14 m/s a car turns <= 6/14 rad/s: over 0.2 s 4.9 deg, + 1.5 deg slack.
  EXPECT_TRUE(plausible(pred, pred * pose(0.1, 0, 5.0), cfg, 0.2, 14.0));
  EXPECT_FALSE(plausible(pred, pred * pose(0.1, 0, 8.7), cfg, 0.2, 14.0));
  EXPECT_FALSE(plausible(pred, pred * pose(4.5, 0, 0), cfg, 0.2, 14.0));  // > 2 m per 0.1 s
}

TEST(MotionChecks, WithOdometryOnlyItsSmallErrorsMayBeCorrected) {
  // The 8.7 deg jump that a few stray edges on an open street caused (city drive, t = 33.9 s)
  // passes the car-dynamics bound at low estimated speed but not the odometry's.
  const Config cfg;  // slack 0.25 m, 0.5 deg per 0.1 s
  const Pose3 pred = pose(40, 520, -96);
  const Pose3 jump = pred * pose(0, 0, -8.7);
  EXPECT_TRUE(plausible(pred, jump, cfg, 0.2, 5.6));
  EXPECT_FALSE(plausibleWithOdometry(pred, jump, cfg, 0.2));
  EXPECT_TRUE(
      plausibleWithOdometry(pred, pred * pose(0.3, -0.2, 0.8), cfg, 0.2));      // within 2x slack
  EXPECT_FALSE(plausibleWithOdometry(pred, pred * pose(0.6, 0, 0), cfg, 0.2));  // slid 0.6 m
  // Roll and pitch are the planes' business: a 3 deg pitch change is not an odometry conflict.
  Pose3 pitched = pred;
  pitched.linear() = pred.rotation() * Eigen::AngleAxisd(0.05, Vec3::UnitY()).toRotationMatrix();
  EXPECT_TRUE(plausibleWithOdometry(pred, pitched, cfg, 0.1));
}

TEST(MotionChecks, LevelledMovesRollAndPitchTowardsTheImuAndKeepsHeading) {
  const double deg = std::numbers::pi / 180.0;
  Pose3 T = pose(5.0, -2.0, 30.0);
  T.linear() = T.linear() * Eigen::AngleAxisd(-3.0 * deg, Vec3::UnitY()).toRotationMatrix() *
               Eigen::AngleAxisd(2.0 * deg, Vec3::UnitX()).toRotationMatrix();
  const auto rpy = [](const Pose3& P) {
    const Mat3 R = P.rotation();
    return Vec3(std::atan2(R(2, 1), R(2, 2)), -std::asin(R(2, 0)), std::atan2(R(1, 0), R(0, 0)));
  };
  const Vec3 full = rpy(levelled(T, 0.0, 0.0, 1.0));
  EXPECT_NEAR(full.x(), 0.0, 1e-12);
  EXPECT_NEAR(full.y(), 0.0, 1e-12);
  EXPECT_NEAR(full.z(), 30.0 * deg, 1e-12);
  const Pose3 half = levelled(T, 1.0 * deg, 1.0 * deg, 0.5);
  EXPECT_NEAR(rpy(half).x(), 1.5 * deg, 1e-12);   // roll 2 -> 1.5 deg
  EXPECT_NEAR(rpy(half).y(), -1.0 * deg, 1e-12);  // pitch -3 -> -1 deg
  EXPECT_NEAR(rpy(half).z(), 30.0 * deg, 1e-12);
  EXPECT_TRUE(half.translation().isApprox(T.translation()));
  EXPECT_TRUE(levelled(T, 0.0, 0.0, 0.0).isApprox(T, 1e-12));
}

TEST(MotionChecks, LoopCorrectionIsBoundedByTheDriftSinceTheLastClosure) {
  Config cfg;
  cfg.loop.max_correction_m = 1.0;
  cfg.loop.correction_per_m = 0.002;
  EXPECT_TRUE(plausibleLoopCorrection(0.9, 0.0, cfg));
  EXPECT_FALSE(plausibleLoopCorrection(3.0, 50.0, cfg));   // a 3 m jump 50 m after a closure
  EXPECT_TRUE(plausibleLoopCorrection(3.0, 1500.0, cfg));  // ... after 1.5 km it may be drift
  EXPECT_FALSE(plausibleLoopCorrection(3.0, 900.0, cfg));
  cfg.loop.max_correction_m = -1.0;  // no bound
  EXPECT_TRUE(plausibleLoopCorrection(100.0, 0.0, cfg));
}

TEST(MotionChecks, YawPriorFollowsTheGyroSpecOfTheDrive) {
  const Config cfg;  // 0.02 deg, tuned for a 0.1 deg/s noise + 0.05 deg/s bias gyro; floor 0.0002
  EXPECT_DOUBLE_EQ(yawPriorSigmaDeg(cfg, std::nullopt), 0.02);
  // The simulated default gyro is the reference: the tuned sigma exactly.
  EXPECT_DOUBLE_EQ(yawPriorSigmaDeg(cfg, OdometrySpec{0.01, 0.05, 0.05, 0.1}), 0.02);
  // A noise-free gyro is trusted down to the floor; a ten times noisier one gets ~ten times the
  // sigma.
  EXPECT_DOUBLE_EQ(yawPriorSigmaDeg(cfg, OdometrySpec{}), 0.0002);
  EXPECT_NEAR(yawPriorSigmaDeg(cfg, OdometrySpec{0, 0, 0.5, 1.0}), 0.2, 1e-12);
  Config off = cfg;  // the prior switched off stays off
  off.odometry.prior_sigma_deg = 0.0;
  EXPECT_DOUBLE_EQ(yawPriorSigmaDeg(off, OdometrySpec{}), 0.0);
  Config fixed = cfg;  // no reference: the configured sigma whatever the drive says
  fixed.odometry.prior_ref_noise_deg_s = fixed.odometry.prior_ref_bias_deg_s = 0.0;
  EXPECT_DOUBLE_EQ(yawPriorSigmaDeg(fixed, OdometrySpec{}), 0.02);
}

}  // namespace
}  // namespace slamroute::evaluate
