// The body on its suspension: pitch under braking and accelerating, level at constant speed,
// roll on a cambered road.
#include <gtest/gtest.h>

#include <cmath>

#include "WorldTestNet.hpp"
#include "slamroute/core/Odometry.hpp"
#include "slamroute/simulate/VehicleBody.hpp"

namespace slamroute::simulate {
namespace {

/// Sensor path along +x at y, 1.8 m up: accelerate at 2 m/s^2 for 5 s, 10 m/s for 10 s, brake
/// at 2 m/s^2 for 5 s; 10 Hz.
Trajectory straightRun(double y) {
  Trajectory p;
  double x = 10, v = 0;
  for (int i = 0; i <= 200; ++i) {
    const double t = 0.1 * i;
    StampedPose s;
    s.t = t;
    s.T_world_body.translation() = Vec3(x, y, 1.8);
    p.push_back(s);
    const double a = t < 5 ? 2.0 : t < 15 ? 0.0 : -2.0;
    x += v * 0.1 + 0.5 * a * 0.01;
    v += a * 0.1;
  }
  return p;
}

TEST(VehicleBody, NoseDivesWhenBrakingSquatsWhenAcceleratingLevelAtConstantSpeed) {
  TriangleMesh plane;
  testnet::addQuad(plane, Point3(-100, -100, 0), Point3(500, -100, 0), Point3(500, 100, 0),
                   Point3(-100, 100, 0), SurfaceKind::Road);
  const World w = World::fromMesh(plane);
  const Trajectory out = vehicleSensorPoses(straightRun(0), w, VehicleBodyConfig{}, 1.8);
  auto pitchAt = [&](int i) {
    return attitudeOf(out[static_cast<std::size_t>(i)].T_world_body.rotation()).pitch_rad;
  };
  const double deg = M_PI / 180;
  // Z-Y-X pitch > 0 is nose down; the static deflection is 0.15 deg per m/s^2
  EXPECT_LT(pitchAt(40), -0.2 * deg);  // accelerating: nose up
  EXPECT_GT(pitchAt(190), 0.2 * deg);  // braking: nose down
  EXPECT_NEAR(pitchAt(40), -0.3 * deg, 0.05 * deg);
  EXPECT_NEAR(pitchAt(120), 0.0, 1e-5);  // constant speed on a flat road: level
  for (const auto& p : out) EXPECT_NEAR(attitudeOf(p.T_world_body.rotation()).roll_rad, 0.0, 1e-9);
  EXPECT_NEAR(out[120].T_world_body.translation().z(), 1.8, 1e-4);
}

TEST(VehicleBody, RollsWithTheCamberOfTheRoad) {
  // grid street J0_0 -> J1_0 along +x, lane centre y = -1.6, crown on the left: the right
  // wheels stand lower, the body rolls right side down by about the 2 % cross-fall
  // wheels; the same world without camber (same relief) tells the camber's share
  WorldConfig flat;
  flat.road_camber_pct = 0;
  const World w = World::build(testnet::gridNet(2, 160), WorldConfig{}, 5);
  const World w0 = World::build(testnet::gridNet(2, 160), flat, 5);
  const Trajectory path = straightRun(-1.6);
  const Trajectory out = vehicleSensorPoses(path, w, VehicleBodyConfig{}, 1.8);
  const Trajectory out0 = vehicleSensorPoses(path, w0, VehicleBodyConfig{}, 1.8);
  double roll = 0;
  int n = 0;
  for (std::size_t i = 60; i < 140; ++i) {
    if (out[i].T_world_body.translation().x() < 30 || out[i].T_world_body.translation().x() > 130)
      continue;
    roll += attitudeOf(out[i].T_world_body.rotation()).roll_rad -
            attitudeOf(out0[i].T_world_body.rotation()).roll_rad;
    ++n;
  }
  ASSERT_GT(n, 10);
  EXPECT_NEAR(roll / n, std::atan(0.02), 0.001);
}

TEST(VehicleBody, RejectsBadSettings) {
  VehicleBodyConfig c;
  c.damping_ratio = 0;
  EXPECT_THROW(validate(c), std::invalid_argument);
  c = VehicleBodyConfig{};
  c.wheelbase_m = -1;
  EXPECT_THROW(validate(c), std::invalid_argument);
}

}  // namespace
}  // namespace slamroute::simulate
