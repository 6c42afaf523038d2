// The SLAM's motion model (evaluate/src/slam/MotionModel): prediction, velocity updates and
// plausibility with known motions.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "slam/MotionModel.hpp"
#include "slamroute/evaluate/MotionChecks.hpp"

namespace slamroute::evaluate {
namespace {

Pose3 forward(double x, double yaw_deg = 0.0) {
  Pose3 T = Pose3::Identity();
  T.translation() = Vec3(x, 0, 0);
  T.linear() =
      Eigen::AngleAxisd(yaw_deg * std::numbers::pi / 180.0, Vec3::UnitZ()).toRotationMatrix();
  return T;
}

TEST(MotionModel, ConstantVelocityExtrapolatesTheGivenMotion) {
  const Config cfg;
  slam::MotionModel m(cfg, Pose3::Identity());
  m.setInitialMotion(forward(1.0), 0.1);  // 10 m/s
  m.recordFrame(0.0, Pose3::Identity());
  EXPECT_NEAR(m.predict(0.25).translation().x(), 2.5, 1e-12);
  const slam::Prediction p = m.predictStep(0.2);
  EXPECT_NEAR(p.speed_mps, 10.0, 1e-12);
  EXPECT_NEAR(p.scale, 2.0, 1e-12);
  EXPECT_DOUBLE_EQ(p.t, 0.2);
}

TEST(MotionModel, WheelOdometryPredictsInsteadOfTheVelocity) {
  const Config cfg;
  slam::MotionModel m(cfg, Pose3::Identity());
  m.setInitialMotion(forward(1.0), 0.1);
  m.setOdometry(WheelOdometry({{0.0, 5.0, 0.0}, {10.0, 5.0, 0.0}}));  // 5 m/s straight
  m.recordFrame(0.0, Pose3::Identity());
  EXPECT_NEAR(m.predict(1.0).translation().x(), 5.0, 1e-9);
  EXPECT_NEAR(m.motionOver(2.0, 0.1).translation().x(), 0.5, 1e-9);
}

// A registered step with a sideways and vertical component and a roll: without odometry the
// prediction keeps the car's part (0.5 m forward, 4 deg of yaw along the chord; 5 m/s, so the
// turn-rate clamp does not act), with vehicle_motion off the whole 6-DoF motion.
TEST(MotionModel, WithoutOdometryTheVelocityIsACarsForwardSpeedAndYawRate) {
  Pose3 step = forward(0.5, 4.0);
  step.translation() = Vec3(0.5, 0.08, 0.05);
  step.linear() = step.linear() * Eigen::AngleAxisd(0.05, Vec3::UnitX()).toRotationMatrix();
  const double d = std::hypot(0.5, 0.08), half = 2.0 * std::numbers::pi / 180.0;
  for (const bool car : {true, false}) {
    Config cfg;
    cfg.odometry.vehicle_motion = car;
    slam::MotionModel m(cfg, Pose3::Identity());
    m.recordFrame(0.0, Pose3::Identity());
    m.update(slam::MotionModel::Outcome::Registered, true, Pose3::Identity(), step, 0.1);
    m.recordFrame(0.1, Pose3::Identity());
    const Pose3 p = m.predict(0.2);
    if (car) {
      EXPECT_NEAR(p.translation().x(), d * std::cos(half), 1e-9);
      EXPECT_NEAR(p.translation().y(), d * std::sin(half), 1e-9);
      EXPECT_NEAR(p.translation().z(), 0.0, 1e-12);
      EXPECT_NEAR(rotationAngle(p), 2 * half, 1e-9);  // the yaw alone: no roll left
    } else {
      EXPECT_TRUE(p.isApprox(step, 1e-9));
    }
  }
}

// Straight at 5 m/s, then registrations that turn +4, -1.5 and +4 deg per 0.1 s (40, -15, 40
// deg/s; what single wrong registrations on a feature-poor street look like): the predicted turn
// rate moves at most max_yaw_accel_deg_s2 (60 deg/s^2: 6 deg/s per step) towards each. Two in a
// row that agree on the rate (within 6 deg/s) are a turn the car makes (SUMO turns that fast):
// the prediction takes it. Unbounded (0) it follows every registration at once.
TEST(MotionModel, WithoutOdometryTheTurnRateFollowsOnlyATurnTwoRegistrationsAgreeOn) {
  const double steps_deg[] = {4.0, -1.5, 4.0, 4.0, 4.0};
  const double bounded[] = {6.0, 0.0, 6.0, 40.0, 40.0};
  for (const double accel : {60.0, 0.0}) {
    Config cfg;
    cfg.odometry.max_yaw_accel_deg_s2 = accel;
    slam::MotionModel m(cfg, Pose3::Identity());
    m.recordFrame(0.0, Pose3::Identity());
    m.update(slam::MotionModel::Outcome::Registered, true, Pose3::Identity(), forward(0.5), 0.1);
    EXPECT_NEAR(m.turnRateDegPerS(), 0.0, 1e-9);
    for (int k = 0; k < 5; ++k) {
      m.update(slam::MotionModel::Outcome::Registered, true, Pose3::Identity(),
               forward(0.5, steps_deg[k]), 0.1);
      const double want = accel > 0 ? bounded[k] : std::abs(10.0 * steps_deg[k]);
      EXPECT_NEAR(m.turnRateDegPerS(), want, 1e-6) << "accel " << accel << " step " << k;
    }
    EXPECT_NEAR(m.predictStep(0.1).speed_mps, 5.0, 1e-6);
  }
}

// Without odometry a sweep is deskewed with the mean of the last deskew_increments registered
// velocities: steps of 0.6 m turning 1 deg and 0.7 m turning 2 deg per 0.1 s give a sweep motion
// of the mean chord and 1.5 deg (the last step alone with 1); a failed scan empties the history,
// so the next sweep takes the (faded) velocity again.
class MotionModelDeskew : public ::testing::TestWithParam<int> {};

TEST_P(MotionModelDeskew, TheSweepMovesByTheMeanOfTheLastRegisteredSteps) {
  Config cfg;
  cfg.odometry.max_yaw_accel_deg_s2 = 0;  // every registered turn rate taken at once
  cfg.features.deskew_increments = GetParam();
  slam::MotionModel m(cfg, Pose3::Identity());
  m.recordFrame(0.0, Pose3::Identity());
  using Outcome = slam::MotionModel::Outcome;
  m.update(Outcome::Registered, true, Pose3::Identity(), forward(0.6, 1.0), 0.1);
  m.update(Outcome::Registered, true, Pose3::Identity(), forward(0.7, 2.0), 0.1);
  const auto chord = [](double d, double yaw_deg) {
    const double half = yaw_deg * std::numbers::pi / 360.0;
    return Vec3(d * std::cos(half), d * std::sin(half), 0.0);
  };
  const bool mean = GetParam() == 2;
  const Vec3 want = mean ? 0.5 * (chord(0.6, 1.0) + chord(0.7, 2.0)) : chord(0.7, 2.0);
  const Pose3 sweep = m.motionOver(0.1, 0.1);
  EXPECT_TRUE(sweep.translation().isApprox(want, 1e-9)) << sweep.translation().transpose();
  EXPECT_NEAR(rotationAngle(sweep) * 180.0 / std::numbers::pi, mean ? 1.5 : 2.0, 1e-9);
  // Half a sweep: half the motion.
  EXPECT_NEAR(m.motionOver(0.1, 0.05).translation().x(), 0.5 * want.x(), 1e-9);
  m.update(Outcome::Failed, false, Pose3::Identity(), forward(9.0, 90.0), 0.1);
  EXPECT_NEAR(rotationAngle(m.motionOver(0.2, 0.1)) * 180.0 / std::numbers::pi,
              2.0 * cfg.odometry.failed_turn_decay, 1e-9);
}

INSTANTIATE_TEST_SUITE_P(LastStepOrMeanOfTwo, MotionModelDeskew, ::testing::Values(1, 2));

TEST(MotionModel, BeforeTheFirstFrameItStandsAtTheStartPose) {
  const Config cfg;
  const Pose3 start = forward(7.0, 30.0);
  slam::MotionModel m(cfg, start);
  EXPECT_FALSE(m.started());
  EXPECT_TRUE(m.predict(5.0).isApprox(start));
}

TEST(MotionModel, ARegisteredStepSetsTheVelocityButNotAnImpossibleTurnRate) {
  const Config cfg;
  slam::MotionModel m(cfg, Pose3::Identity());
  m.recordFrame(0.0, Pose3::Identity());
  // 1 m and 45 deg in 0.1 s: 450 deg/s, far beyond a car at 10 m/s.
  m.update(slam::MotionModel::Outcome::Registered, true, Pose3::Identity(), forward(1.0, 45.0),
           0.1);
  EXPECT_TRUE(m.hasVelocity());
  const double rate = m.turnRateDegPerS();
  EXPECT_NEAR(rate, maxTurnRate(cfg, 10.0) * 180.0 / std::numbers::pi, 1e-6);
  EXPECT_LT(rate, 450.0);
}

TEST(MotionModel, AFailedStepKeepsTheSpeedAndLetsTheTurnFade) {
  const Config cfg;
  slam::MotionModel m(cfg, Pose3::Identity());
  m.recordFrame(0.0, Pose3::Identity());
  m.update(slam::MotionModel::Outcome::Registered, true, Pose3::Identity(), forward(1.0, 1.0), 0.1);
  const double before = m.turnRateDegPerS();
  m.update(slam::MotionModel::Outcome::Failed, false, Pose3::Identity(), forward(9.0, 90.0), 0.1);
  EXPECT_NEAR(m.turnRateDegPerS(), before * cfg.odometry.failed_turn_decay, 1e-9);
  EXPECT_NEAR(m.predictStep(0.1).speed_mps, 10.0, 1e-9);
  m.update(slam::MotionModel::Outcome::Relocalised, false, Pose3::Identity(), forward(9.0, 90.0),
           0.1);
  EXPECT_NEAR(m.turnRateDegPerS(), 0.0, 1e-9);
}

TEST(MotionModel, AJumpOfMetresInOneScanIsNotPlausible) {
  const Config cfg;
  slam::MotionModel m(cfg, Pose3::Identity());
  m.setInitialMotion(forward(1.0), 0.1);
  m.recordFrame(0.0, Pose3::Identity());
  const slam::Prediction p = m.predictStep(0.1);
  EXPECT_TRUE(m.plausibleStep(p.T_world, p.T_world * forward(0.3), p));
  EXPECT_FALSE(m.plausibleStep(p.T_world, p.T_world * forward(5.0), p));
}

// With wheel odometry a registration may move the prediction 0.25 m per 0.1 s. After scans that
// failed to register, the prediction has gone on from an uncorrected pose, so the slack counts the
// time since the last registered scan (0.4 s after three failures at 10 Hz: 1 m), at most
// slack_since_fix_max_s (here 0.5 s) beyond the step (after 30 failures: 0.6 s, 1.5 m); with 0, the
// step's 0.25 m alone. A registered scan brings it back to the step.
class MotionModelSlack : public ::testing::TestWithParam<double> {};

TEST_P(MotionModelSlack, TheSlackCountsTheTimeSinceTheLastRegisteredScan) {
  Config cfg;
  cfg.odometry.slack_since_fix_max_s = GetParam();
  const bool grows = GetParam() > 0;
  slam::MotionModel m(cfg, Pose3::Identity());
  m.setOdometry(WheelOdometry({{0.0, 10.0, 0.0}, {100.0, 10.0, 0.0}}));
  m.setInitialMotion(forward(1.0), 0.1);
  m.recordFrame(0.0, Pose3::Identity());
  using Outcome = slam::MotionModel::Outcome;
  const auto step = [&](Outcome o, int k) {
    m.update(o, o == Outcome::Registered, m.lastPose(), m.predict(0.1 * k), 0.1);
    m.recordFrame(0.1 * k, m.predict(0.1 * k));
  };
  const auto sideways = [&](double t, double y) {
    const slam::Prediction p = m.predictStep(t);
    Pose3 off = Pose3::Identity();
    off.translation().y() = y;
    return m.plausibleStep(p.T_world, p.T_world * off, p);
  };
  step(Outcome::Registered, 1);
  for (int k = 2; k <= 4; ++k) step(Outcome::Failed, k);
  EXPECT_NEAR(m.predictStep(0.5).since_fix_s, 0.4, 1e-9);
  EXPECT_TRUE(sideways(0.5, 0.2));
  EXPECT_EQ(sideways(0.5, 0.95), grows);
  EXPECT_FALSE(sideways(0.5, 1.05));
  for (int k = 5; k <= 31; ++k) step(Outcome::Failed, k);
  EXPECT_EQ(sideways(3.2, 1.45), grows);
  EXPECT_FALSE(sideways(3.2, 1.55));
  step(Outcome::Registered, 32);
  EXPECT_TRUE(sideways(3.3, 0.2));
  EXPECT_FALSE(sideways(3.3, 0.3));
}

INSTANTIATE_TEST_SUITE_P(GrowingOrStepOnly, MotionModelSlack, ::testing::Values(0.5, 0.0));

TEST(MotionModel, TheOdometryPriorWeighsYawAndAFadingAlongPriorByDefault) {
  const Config cfg;
  slam::MotionModel m(cfg, Pose3::Identity());
  AlignOptions o;
  slam::Prediction p;
  m.addMotionPrior(o, p);
  EXPECT_EQ(o.prior_weight.norm(), 0.0);  // no odometry and no velocity yet: no prior
  m.setOdometry(WheelOdometry({{0.0, 5.0, 0.0}, {10.0, 5.0, 0.0}}));
  m.addMotionPrior(o, p);
  const double sigma = cfg.odometry.prior_sigma_deg * std::numbers::pi / 180.0;
  EXPECT_NEAR(o.prior_weight(2), std::pow(cfg.odometry.prior_registration_sigma_m / sigma, 2),
              1e-6);
  EXPECT_NEAR(o.prior_weight(3), std::pow(0.05 / 0.005, 2), 1e-9);  // along: 0.005 m per 0.1 s
  EXPECT_EQ(o.prior_fade_info(3), 0.05);  // ... only where the scan says little that way
  EXPECT_EQ(o.prior_weight(4), 0.0);      // sideways: none, a car slips in turns
}

TEST(MotionModel, WithoutOdometryTheConstantVelocityIsAFadingPriorAlongTheHeadingAndInYaw) {
  Config cfg;
  cfg.odometry.velocity_prior_along_sigma_m = 0.01;
  slam::MotionModel m(cfg, Pose3::Identity());
  m.setInitialMotion(forward(1.5), 0.1);
  m.recordFrame(0.0, Pose3::Identity());
  AlignOptions o;
  const slam::Prediction p = m.predictStep(0.2);  // stride 2: the sigmas double
  m.addMotionPrior(o, p);
  EXPECT_NEAR(o.prior.translation().x(), 3.0, 1e-12);  // towards the prediction
  const double r = cfg.odometry.prior_registration_sigma_m;
  EXPECT_NEAR(o.prior_weight(3), std::pow(r / 0.02, 2), 1e-9);
  EXPECT_EQ(o.prior_fade_info(3), cfg.odometry.velocity_prior_fade_info);
  const double yaw_sigma = 2 * cfg.odometry.velocity_prior_yaw_sigma_deg * std::numbers::pi / 180;
  EXPECT_NEAR(o.prior_weight(2), std::pow(r / yaw_sigma, 2), 1e-6);  // on by default
  EXPECT_EQ(o.prior_fade_info(2), cfg.odometry.velocity_prior_yaw_fade_info);
  o.prior_weight(2) = o.prior_weight(3) = 0.0;
  EXPECT_EQ(o.prior_weight.norm(), 0.0);  // no sideways, vertical, roll or pitch prior
  cfg.odometry.velocity_prior_along_sigma_m = 0.0;
  AlignOptions yaw_only;
  m.addMotionPrior(yaw_only, p);
  EXPECT_EQ(yaw_only.prior_weight(3), 0.0);
  EXPECT_GT(yaw_only.prior_weight(2), 0.0);
  cfg.odometry.velocity_prior_yaw_sigma_deg = 0.0;
  AlignOptions off;
  m.addMotionPrior(off, p);
  EXPECT_EQ(off.prior_weight.norm(), 0.0);
}

TEST(MotionModel, TheAlongPriorWeighsTheHeadingDirectionOnly) {
  Config cfg;
  cfg.odometry.prior_along_sigma_m = 0.005;
  slam::MotionModel m(cfg, Pose3::Identity());
  m.setOdometry(WheelOdometry({{0.0, 5.0, 0.0}, {10.0, 5.0, 0.0}}));
  AlignOptions o;
  slam::Prediction p;
  p.scale = 2.0;  // 0.2 s since the last frame: the sigma doubles
  m.addMotionPrior(o, p);
  EXPECT_NEAR(o.prior_weight(3), std::pow(cfg.odometry.prior_registration_sigma_m / 0.01, 2), 1e-9);
  EXPECT_EQ(o.prior_weight(4), 0.0);  // sideways: the wheels do not see a car slip
  EXPECT_EQ(o.prior_weight(5), 0.0);
}

TEST(MotionModel, RegisteredStepsSetTheWheelScaleOfThePrediction) {
  Config cfg;
  cfg.odometry.wheel_scale_stretch_m = 10.0;
  cfg.odometry.wheel_scale_min_stretches = 2;
  slam::MotionModel m(cfg, Pose3::Identity());
  m.setOdometry(WheelOdometry({{0.0, 10.0, 0.0}, {100.0, 10.0, 0.0}}));  // 10 m/s by the wheels
  m.recordFrame(0.0, Pose3::Identity());
  EXPECT_NEAR(m.predict(0.1).translation().x(), 1.0, 1e-9);
  // The LiDAR measures 0.97 m per 0.1 s: the car is slower than its wheels say.
  Pose3 T = Pose3::Identity();
  for (int k = 1; k <= 30; ++k) {
    const Pose3 next = T * forward(0.97);
    m.measureWheels(T, next, 0.1);
    m.recordFrame(0.1 * k, next);
    T = next;
  }
  EXPECT_NEAR(m.wheelScale(), 0.97, 1e-9);
  EXPECT_NEAR((T.inverse() * m.predict(3.1)).translation().x(), 0.97, 1e-9);
}

}  // namespace
}  // namespace slamroute::evaluate
