// Wheel odometry + gyro: integration against known motions, the odometry.csv format.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "TestUtil.hpp"
#include "slamroute/core/Odometry.hpp"
#include "slamroute/core/OdometrySpec.hpp"

namespace slamroute {
namespace {

WheelOdometry constant(double v, double w, double dt, int n) {
  std::vector<OdometrySample> s;
  for (int i = 0; i < n; ++i) s.push_back({dt * i, v, w});
  return WheelOdometry(std::move(s));
}

TEST(Odometry, StraightAtConstantSpeed) {
  const WheelOdometry o = constant(10.0, 0.0, 0.1, 20);
  const Pose3 m = o.motion(0.25, 1.25);  // 1 s, across sample boundaries
  EXPECT_NEAR(m.translation().x(), 10.0, 1e-9);
  EXPECT_NEAR(m.translation().y(), 0.0, 1e-9);
  EXPECT_NEAR(o.motion(1.0, 1.0).translation().norm(), 0.0, 1e-12);
}

TEST(Odometry, FullCircleClosesAndQuarterHasTheRadius) {
  // v = 10 m/s, one turn in 20 s: radius 10 / (2 pi / 20) = 31.83 m.
  const double w = 2 * std::numbers::pi / 20.0;
  const WheelOdometry o = constant(10.0, w, 0.1, 200);
  const Pose3 full = o.motion(0.0, 20.0);
  EXPECT_NEAR(full.translation().norm(), 0.0, 1e-6);
  const Pose3 quarter = o.motion(0.0, 5.0);  // left turn: ends at (r, r), heading +90 deg
  const double r = 10.0 / w;
  EXPECT_NEAR(quarter.translation().x(), r, 1e-3 * r);
  EXPECT_NEAR(quarter.translation().y(), r, 1e-3 * r);
  EXPECT_NEAR(std::atan2(quarter.rotation()(1, 0), quarter.rotation()(0, 0)), std::numbers::pi / 2,
              1e-9);
  EXPECT_NEAR(o.yawRate(3.33), w, 1e-12);
}

TEST(OdometrySpec, YamlRoundTripAndBadFiles) {
  const auto dir = test::tempDir("odometry_spec");
  EXPECT_FALSE(readOdometrySpec(dir / "none.yaml").has_value());  // optional file
  const OdometrySpec spec{0.01, 0.05, 0.02, 0.1};
  writeOdometrySpec(dir / "odometry.yaml", spec);
  const auto r = readOdometrySpec(dir / "odometry.yaml");
  ASSERT_TRUE(r.has_value());
  EXPECT_DOUBLE_EQ(r->scale_sigma, 0.01);
  EXPECT_DOUBLE_EQ(r->speed_noise_mps, 0.05);
  EXPECT_DOUBLE_EQ(r->gyro_bias_sigma_deg_s, 0.02);
  EXPECT_DOUBLE_EQ(r->gyro_noise_deg_s, 0.1);
  // A partial file keeps 0 (noise-free) for what it does not state.
  test::writeText(dir / "partial.yaml", "gyro_noise_deg_s: 0.3\n");
  EXPECT_DOUBLE_EQ(readOdometrySpec(dir / "partial.yaml")->gyro_noise_deg_s, 0.3);
  EXPECT_DOUBLE_EQ(readOdometrySpec(dir / "partial.yaml")->gyro_bias_sigma_deg_s, 0.0);
  const auto expectError = [&](const char* name, const char* text, const char* fragment) {
    test::writeText(dir / name, text);
    try {
      readOdometrySpec(dir / name);
      FAIL() << name;
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
  };
  expectError("negative.yaml", "gyro_noise_deg_s: -0.1\n", "gyro_noise_deg_s");
  expectError("nan.yaml", "gyro_bias_sigma_deg_s: .nan\n", "gyro_bias_sigma_deg_s");
  expectError("typo.yaml", "gyro_nois_deg_s: 0.1\n", "gyro_nois_deg_s");
  expectError("text.yaml", "gyro_noise_deg_s: fast\n", "gyro_noise_deg_s");
  expectError("broken.yaml", "gyro_noise_deg_s: [0.1\n", "not valid YAML");
}

TEST(Odometry, CsvRoundTripAndBadFiles) {
  const auto dir = test::tempDir("odometry");
  const WheelOdometry o({{0.0, 1.5, 0.01}, {0.1, 1.6, -0.02}, {0.2, 1.7, 0.0}});
  writeOdometryCsv(dir / "odometry.csv", o);
  const WheelOdometry r = readOdometryCsv(dir / "odometry.csv");
  ASSERT_EQ(r.samples().size(), 3u);
  EXPECT_NEAR(r.samples()[1].speed_mps, 1.6, 1e-9);
  EXPECT_NEAR(r.samples()[1].yaw_rate_rad_s, -0.02, 1e-9);
  test::writeText(dir / "bad.csv", "t,speed_mps,yaw_rate_rad_s\n0,1,0\n0.1,x,0\n");
  try {
    readOdometryCsv(dir / "bad.csv");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("bad.csv:3"), std::string::npos) << e.what();
  }
  test::writeText(dir / "order.csv", "0.1,1,0\n0.1,1,0\n");
  EXPECT_THROW(readOdometryCsv(dir / "order.csv"), std::runtime_error);
  EXPECT_THROW(readOdometryCsv(dir / "missing.csv"), std::runtime_error);
}

TEST(Odometry, ImuRollAndPitchRoundTripAndAreOptional) {
  const auto dir = test::tempDir("odometry");
  std::vector<OdometrySample> s = {{0.0, 1.5, 0.01}, {0.1, 1.6, -0.02}};
  s[0].roll_rad = 0.01;
  s[0].pitch_rad = -0.02;
  s[1].roll_rad = 0.015;
  s[1].pitch_rad = 0.03;
  writeOdometryCsv(dir / "tilt.csv", WheelOdometry(s));
  const WheelOdometry r = readOdometryCsv(dir / "tilt.csv");
  ASSERT_TRUE(r.attitude(0.15).has_value());
  EXPECT_NEAR(r.attitude(0.15)->roll_rad, 0.015, 1e-7);
  EXPECT_NEAR(r.attitude(0.05)->pitch_rad, -0.02, 1e-7);
  // Without the two columns there is no attitude; a line with only one of them is an error.
  EXPECT_FALSE(constant(1.0, 0.0, 0.1, 3).attitude(0.1).has_value());
  test::writeText(dir / "half.csv",
                  "t,speed_mps,yaw_rate_rad_s,roll_rad,pitch_rad\n0,1,0,0.1,0.2\n0.1,1,0,0.1\n");
  try {
    readOdometryCsv(dir / "half.csv");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("half.csv:3"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace slamroute

namespace slamroute {
namespace {

// A drive that stops for 5 s (5..10 s), then turns at 0.1 rad/s: a gyro with a 0.01 rad/s bias
// is corrected once 2 s of standstill are confirmed (0.6 s margins: from 5.6 s, confirmed 0.6 s
// later, so from 8.2 s on); the stop's first and last 0.6 s, when a car may already turn, do not
// count (here the gyro reads a turn there that must not enter the bias).
TEST(Odometry, GyroBiasFromStandstill) {
  std::vector<OdometrySample> s;
  const double bias = 0.01;
  for (int k = 0; k <= 200; ++k) {
    const double t = 0.1 * k;
    const bool stopped = t >= 5.0 - 1e-9 && t < 10.0 - 1e-9;
    double true_rate = t >= 10.0 - 1e-9 ? 0.1 : 0.0;
    if (t > 9.65 && t < 10.0) true_rate = 0.3;  // turning as it starts
    s.push_back({t, stopped ? 0.0 : 10.0, true_rate + bias});
  }
  const GyroBiasResult r = removeStandstillGyroBias(WheelOdometry(s), 0.05, 2.0, 0.6);
  EXPECT_NEAR(r.final_bias_rad_s, bias, 1e-12);
  EXPECT_GT(r.standstill_s, 3.0);
  EXPECT_LT(r.standstill_s, 4.0);
  const auto& c = r.odometry.samples();
  EXPECT_NEAR(c[10].yaw_rate_rad_s, bias, 1e-12);  // t = 1 s: no standstill seen yet
  EXPECT_NEAR(c[75].yaw_rate_rad_s, bias, 1e-12);  // t = 7.5 s: not yet 2 s confirmed
  EXPECT_NEAR(c[90].yaw_rate_rad_s, 0.0, 1e-12);   // t = 9 s: corrected
  EXPECT_NEAR(c[150].yaw_rate_rad_s, 0.1, 1e-12);  // the turn keeps its true rate
  const Pose3 m = r.odometry.motion(10.0, 20.0);
  EXPECT_NEAR(Eigen::AngleAxisd(m.rotation()).angle(), 1.0, 1e-9);
  // No standstill at all: nothing changes.
  std::vector<OdometrySample> moving(s);
  for (auto& x : moving) x.speed_mps = 10.0;
  const GyroBiasResult none = removeStandstillGyroBias(WheelOdometry(moving));
  EXPECT_EQ(none.standstill_s, 0.0);
  EXPECT_NEAR(none.odometry.samples()[150].yaw_rate_rad_s, 0.1 + bias, 1e-12);
}

}  // namespace
}  // namespace slamroute
