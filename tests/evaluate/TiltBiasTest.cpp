// The IMU's pitch bias measured at loop closures (evaluate/src/slam/TiltBias): laps of a loop
// whose estimated height drifts by the bias left in effect, each closed at its start.
#include <gtest/gtest.h>

#include <cmath>

#include "slam/TiltBias.hpp"

namespace slamroute::evaluate {
namespace {

OdometryConfig tiltConfig() {
  OdometryConfig c;
  c.tilt_bias_min_path_m = 150.0;
  c.tilt_bias_closures = 5;
  c.tilt_bias_min_closures = 2;
  c.tilt_bias_max_deg = 0.5;
  return c;
}

/// A car on a 400 m loop at true height 0, keyframes every 10 m. The pitch the SLAM keeps is the
/// IMU's less the estimated bias; pitch is positive nose down, so the estimate sinks by
/// (bias - estimate) per metre; each lap
/// ends with a closure to the first keyframe that puts the height back (a pose graph's anchor).
class Laps {
 public:
  Laps(slam::TiltBias& tilt, double bias_rad) : tilt_(tilt), bias_rad_(bias_rad) {
    tilt_.addKeyframe(position());
  }
  /// One lap; returns the height error just before its closure [m].
  double lap(double closure_error_m = 0.0) {
    for (int i = 1; i <= 40; ++i) {
      z_m_ -= (bias_rad_ - tilt_.pitchBias()) * 10.0;
      along_m_ += 10.0;
      tilt_.addKeyframe(position());
      ++newest_;
    }
    const double error = z_m_;
    tilt_.addClosure(0, -z_m_ + closure_error_m);
    z_m_ = 0.0;
    return error;
  }

 private:
  Vec3 position() const { return Vec3(along_m_, 0.0, z_m_); }
  slam::TiltBias& tilt_;
  double bias_rad_;
  double z_m_ = 0.0, along_m_ = 0.0;
  int newest_ = 0;
};

TEST(TiltBias, ClosuresMeasureTheBiasAndTheHeightStopsDrifting) {
  const OdometryConfig c = tiltConfig();
  slam::TiltBias tilt(c);
  Laps laps(tilt, 0.002);  // 0.11 deg nose down: 0.8 m lower after a 400 m lap
  EXPECT_NEAR(laps.lap(), -0.8, 0.02);
  EXPECT_EQ(tilt.pitchBias(), 0.0);  // one closure: not enough yet
  EXPECT_NEAR(laps.lap(), -0.8, 0.02);
  EXPECT_NEAR(tilt.pitchBias(), 0.002, 1e-4);
  EXPECT_NEAR(laps.lap(), 0.0, 0.02);  // the bias taken off: no climb
  EXPECT_NEAR(tilt.pitchBias(), 0.002, 1e-4);
}

TEST(TiltBias, AClosureFarOffDoesNotMoveTheEstimate) {
  const OdometryConfig c = tiltConfig();
  slam::TiltBias tilt(c);
  Laps laps(tilt, -0.001);
  laps.lap();
  laps.lap();
  laps.lap(3.0);  // a closure that put the car 3 m too high
  EXPECT_NEAR(tilt.pitchBias(), -0.001, 1e-4);
}

TEST(TiltBias, ShortPathsAreNotMeasured) {
  const OdometryConfig c = tiltConfig();
  slam::TiltBias tilt(c);
  tilt.addKeyframe(Vec3::Zero());
  for (int i = 1; i <= 10; ++i) tilt.addKeyframe(Vec3(10.0 * i, 0.0, 0.0));  // 100 m
  tilt.addClosure(0, 0.5);
  for (int i = 11; i <= 20; ++i) tilt.addKeyframe(Vec3(10.0 * i, 0.0, 0.0));
  tilt.addClosure(0, 0.5);  // 100 m since the last closure: drift restarted there
  EXPECT_EQ(tilt.pitchBias(), 0.0);
}

TEST(TiltBias, StaysWithinItsBoundAndOffWithoutAPath) {
  OdometryConfig c = tiltConfig();
  slam::TiltBias bounded(c);
  Laps fast(bounded, 0.05);
  fast.lap();
  fast.lap();
  EXPECT_NEAR(bounded.pitchBias(), 0.5 * M_PI / 180.0, 1e-12);
  c.tilt_bias_min_path_m = 0.0;
  slam::TiltBias off(c);
  Laps laps(off, 0.002);
  laps.lap();
  laps.lap();
  EXPECT_EQ(off.pitchBias(), 0.0);
}

}  // namespace
}  // namespace slamroute::evaluate
