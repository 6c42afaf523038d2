// The recorded path made drivable: SUMO's sideways jumps spread out, no crabbing, a standing car
// stays put, curves keep their shape.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <stdexcept>

#include "slamroute/core/Yaw.hpp"
#include "slamroute/simulate/DrivablePath.hpp"

namespace slamroute::simulate {
namespace {

using Vec2 = Eigen::Vector2d;

/// 10 Hz poses at the positions `where(t)` for t in [0, duration], each turned to SUMO's lane
/// angle `heading` (which makeDrivable replaces).
Trajectory sampled(double duration, const std::function<Vec2(double)>& where, double heading) {
  Trajectory p;
  for (int i = 0; 0.1 * i <= duration + 1e-9; ++i) {
    StampedPose s;
    s.t = 0.1 * i;
    s.T_world_body.translation() << where(s.t), 0.0;
    s.T_world_body.linear() = Eigen::AngleAxisd(heading, Vec3::UnitZ()).toRotationMatrix();
    p.push_back(s);
  }
  return p;
}

Vec2 xy(const StampedPose& p) { return p.T_world_body.translation().head<2>(); }

/// Largest step across the body's heading (halfway between the two poses'), from each pose to
/// the next [m].
double largestSidewaysStep(const Trajectory& p) {
  double worst = 0.0;
  for (std::size_t i = 0; i + 1 < p.size(); ++i) {
    const Vec2 step = xy(p[i + 1]) - xy(p[i]);
    const Vec2 left = (p[i].T_world_body.linear().col(1) + p[i + 1].T_world_body.linear().col(1))
                          .head<2>()
                          .normalized();
    worst = std::max(worst, std::abs(step.dot(left)));
  }
  return worst;
}

/// Along +x at 5 m/s; at 20 s SUMO moves the car 1.4 m to the left in three 0.1 s steps.
Vec2 straightWithJump(double t) {
  const double y = 1.4 * std::clamp((t - 20.0) / 0.3, 0.0, 1.0);
  return {5.0 * t, y};
}

TEST(DrivablePath, ASidewaysJumpBecomesALaneChangeTheWheelsCanSee) {
  Trajectory p = sampled(40.0, straightWithJump, 0.0);
  ASSERT_GT(largestSidewaysStep(p), 0.45);  // SUMO's steps: 0.47 m across the lane angle
  makeDrivable(p, 2.5);
  // No step moves more than 2 cm across the heading: the jump is now a turn, which the gyro
  // sees, and the wheels measure the whole step.
  EXPECT_LT(largestSidewaysStep(p), 0.02);
  // Spread over the next metres (the kernel is 10 m wide), not carried further: away from the
  // jump the path is SUMO's to a millimetre (the car steers back onto it within metres), the
  // heading along the street.
  for (const auto& s : p) {
    const double t = s.t, x = xy(s).x();
    if (t < 18.0 || (t > 22.5 && t < 39.0)) {
      EXPECT_NEAR(xy(s).y(), straightWithJump(t).y(), 1e-3) << t;
      EXPECT_NEAR(x, 5.0 * t, 1e-3) << t;
      EXPECT_NEAR(yawOf(s.T_world_body), 0.0, 1e-3) << t;
    }
  }
  // The turn it takes is gentle: at most 1.4 m over 5 m sideways (16 degrees).
  double most = 0.0;
  for (const auto& s : p) most = std::max(most, std::abs(yawOf(s.T_world_body)));
  EXPECT_GT(most, 0.15);
  EXPECT_LT(most, std::atan(1.4 / 5.0) + 0.01);
}

TEST(DrivablePath, AStandingCarStaysPutAndKeepsItsHeading) {
  // 10 m/s along +y, standing at y = 100 from 10 s to 30 s, then on.
  auto where = [](double t) {
    return Vec2(3.0, t < 10 ? 10.0 * t : t < 30 ? 100.0 : 100.0 + 10.0 * (t - 30.0));
  };
  Trajectory p = sampled(40.0, where, 1.0);  // a lane angle that is wrong by 0.57 rad
  makeDrivable(p, 2.5);
  for (const auto& s : p) {
    EXPECT_NEAR(yawOf(s.T_world_body), M_PI / 2, 1e-6) << s.t;
    if (s.t > 10.6 && s.t < 29.4) {
      EXPECT_NEAR(xy(s).y(), 100.0, 1e-6) << s.t;
    }
  }
  EXPECT_LT(largestSidewaysStep(p), 1e-6);
}

TEST(DrivablePath, ACurveKeepsItsRadiusAndHeadingAlongIt) {
  // A circle of radius 20 m at 10 m/s (0.5 rad/s), counter-clockwise from (20, 0).
  auto where = [](double t) { return Vec2(20.0 * std::cos(0.5 * t), 20.0 * std::sin(0.5 * t)); };
  Trajectory p = sampled(10.0, where, 0.0);
  makeDrivable(p, 2.5);
  for (const auto& s : p) {
    if (s.t < 1.0 || s.t > 9.0) continue;  // the path's ends are held where they are
    // The kernel's variance (2 x 2.5^2 / 3) over 2R: ~0.1 m inside the circle.
    EXPECT_NEAR(xy(s).norm(), 20.0 - 4.17 / 40.0, 0.02) << s.t;
    const double along = std::atan2(xy(s).y(), xy(s).x()) + M_PI / 2;
    EXPECT_NEAR(std::remainder(yawOf(s.T_world_body) - along, 2 * M_PI), 0.0, 0.01) << s.t;
  }
  EXPECT_LT(largestSidewaysStep(p), 0.01);
}

/// SUMO's U-turn between a street's two lanes 3.2 m apart: along +x at 8 m/s for 10 s, a
/// half circle of radius 1.6 m at 2 m/s (2.5 s), back along -x at 8 m/s.
Vec2 uTurn(double t) {
  constexpr double r = 1.6, w = 2.0 / r, t1 = 10.0, t2 = 10.0 + M_PI / w;
  if (t < t1) return {8.0 * t, 0.0};
  if (t < t2) {
    const double a = w * (t - t1);
    return {80.0 + r * std::sin(a), r - r * std::cos(a)};
  }
  return {80.0 - 8.0 * (t - t2), 2.0 * r};
}

TEST(DrivablePath, AUTurnTighterThanACarCanIsTakenWiderWithoutSliding) {
  Trajectory p = sampled(25.0, uTurn, 0.0);
  makeDrivable(p, 2.5);
  // The car only moves along its heading, also through the apex, where the smoothed path itself
  // turns tighter than the heading may. (A step's chord leaves the mean heading by up to 2 cm
  // where the car swings from a full left to a full right turn within 0.1 s at 7 m/s.)
  EXPECT_LT(largestSidewaysStep(p), 0.02);
  // It turns no tighter than 0.5 rad per metre (of arc, a little longer than the chord).
  for (std::size_t i = 0; i + 1 < p.size(); ++i) {
    const double turn =
        std::abs(std::remainder(yawOf(p[i + 1].T_world_body) - yawOf(p[i].T_world_body), 2 * M_PI));
    EXPECT_LE(turn, 0.5 * 1.01 * (xy(p[i + 1]) - xy(p[i])).norm()) << p[i].t;  // chord < arc
  }
  // A 2 m radius needs 4 m between the lanes, not 3.2: at most 1.3 m wider than SUMO's, and
  // back on the other lane, heading along it, within 10 m.
  double widest = 0.0;
  for (const auto& s : p) widest = std::max(widest, xy(s).y());
  EXPECT_GT(widest, 3.2);
  EXPECT_LT(widest, 4.5);
  for (const auto& s : p) {
    if (s.t < 16.0 || s.t > 24.0) continue;
    EXPECT_NEAR(xy(s).y(), 3.2, 0.02) << s.t;
    EXPECT_NEAR(std::abs(yawOf(s.T_world_body)), M_PI, 0.01) << s.t;
  }
}

TEST(DrivablePath, AWindowThatIsNotPositiveIsRejected) {
  Trajectory p = sampled(
      5.0, [](double t) { return Vec2(t, 0.0); }, 0.0);
  EXPECT_THROW(makeDrivable(p, 0.0), std::invalid_argument);
  EXPECT_THROW(makeDrivable(p, std::nan("")), std::invalid_argument);
}

}  // namespace
}  // namespace slamroute::simulate
