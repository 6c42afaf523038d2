#include "slamroute/simulate/VehicleBody.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "slamroute/core/Yaw.hpp"

namespace slamroute::simulate {

namespace {

using Vec2d = Eigen::Vector2d;
constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kSubstep_s = 0.005;
constexpr double kMaxAccel_mps2 = 9.0;  // a real car's grip: keeps SUMO's rare jolts in bounds

/// Road under the four wheels: mean height, and the pitch (nose down > 0) and roll (right side
/// down > 0) of the plane through them, Z-Y-X Euler angles like the body's.
struct RoadUnder {
  double heave = 0, pitch = 0, roll = 0;
};

struct Axis {
  double x = 0, v = 0;
};

/// One axis over dt: x'' = w^2 (u + d - x) + 2 zeta w (u' - x'), a spring and a damper between
/// body and road (u, linear over dt) plus the inertial deflection d; semi-implicit Euler.
void advance(Axis& a, double u0, double u1, double d, double dt, double hz, double zeta) {
  const double w = 2 * std::numbers::pi * hz;
  const int n = std::max(1, static_cast<int>(std::ceil(dt / kSubstep_s)));
  const double h = dt / n, du = (u1 - u0) / dt;
  for (int k = 1; k <= n; ++k) {
    const double u = u0 + du * h * k;
    a.v += (w * w * (u + d - a.x) + 2 * zeta * w * (du - a.v)) * h;
    a.x += a.v * h;
  }
}

/// Height of the carriageway under a wheel, or NaN where the wheel is over something else (a
/// turning car's inner rear wheel may cut across a pavement's corner or the verge beside a
/// junction in the mesh; a real one stays on the road).
double wheelZ(const World& world, const Vec2d& p, double z_lane) {
  const RayHit h = world.castRay(Vec3(p.x(), p.y(), z_lane + 1.0), -Vec3::UnitZ(), 3.0);
  const bool road = h.hit && (h.kind == SurfaceKind::Road || h.kind == SurfaceKind::Deck);
  return road ? z_lane + 1.0 - h.range_m : std::numeric_limits<double>::quiet_NaN();
}

RoadUnder roadUnder(const World& world, const Pose3& T, double mount_height,
                    const VehicleBodyConfig& c) {
  const double yaw = yawOf(T), z_lane = T.translation().z() - mount_height;
  const Vec2d fwd(std::cos(yaw), std::sin(yaw)), left(-fwd.y(), fwd.x());
  const Vec2d front = T.translation().head<2>() - fwd * c.front_overhang_m;
  const Vec2d rear = front - fwd * c.wheelbase_m;
  const Vec2d half = left * (c.track_m / 2);
  double z[4] = {wheelZ(world, front + half, z_lane), wheelZ(world, front - half, z_lane),
                 wheelZ(world, rear + half, z_lane), wheelZ(world, rear - half, z_lane)};
  double sum = 0;
  int n = 0;
  for (double v : z)
    if (std::isfinite(v)) sum += v, ++n;
  for (double& v : z)  // a wheel off the road: level with the others (or the lane)
    if (!std::isfinite(v)) v = n > 0 ? sum / n : z_lane;
  const double fl = z[0], fr = z[1], rl = z[2], rr = z[3];
  RoadUnder r;
  r.heave = (fl + fr + rl + rr) / 4;
  r.pitch = std::atan2((rl + rr - fl - fr) / 2, c.wheelbase_m);
  r.roll = std::atan2((fl + rl - fr - rr) / 2, c.track_m);
  return r;
}

/// Forward speed at each pose (central differences of the path) [m/s].
std::vector<double> speeds(const Trajectory& p) {
  const std::size_t n = p.size();
  std::vector<double> v(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t a = i > 0 ? i - 1 : 0, b = std::min(n - 1, i + 1);
    const double dt = p[b].t - p[a].t;
    if (dt > 0)
      v[i] =
          (p[b].T_world_body.translation() - p[a].T_world_body.translation()).head<2>().norm() / dt;
  }
  return v;
}

/// The body's pose from its state: the axles' midpoint on the road at `heave`, turned by yaw,
/// pitch and roll; returns the sensor's pose on it.
Pose3 sensorPose(const Pose3& T_path, double heave, double pitch, double roll, double mount_height,
                 const VehicleBodyConfig& c) {
  const double yaw = yawOf(T_path);
  const double ahead = c.front_overhang_m + c.wheelbase_m / 2;  // body centre to the bumper
  const Vec3 centre(T_path.translation().x() - ahead * std::cos(yaw),
                    T_path.translation().y() - ahead * std::sin(yaw), heave);
  Pose3 T = Pose3::Identity();
  T.linear() = (Eigen::AngleAxisd(yaw, Vec3::UnitZ()) * Eigen::AngleAxisd(pitch, Vec3::UnitY()) *
                Eigen::AngleAxisd(roll, Vec3::UnitX()))
                   .toRotationMatrix();
  T.translation() = centre + T.linear() * Vec3(ahead, 0, mount_height);
  return T;
}

}  // namespace

void validate(const VehicleBodyConfig& c) {
  auto bad = [](const std::string& m) { throw std::invalid_argument("drive.body: " + m); };
  if (!(c.wheelbase_m > 0) || !(c.track_m > 0) || !(c.front_overhang_m >= 0))
    bad("wheelbase_m and track_m must be > 0, front_overhang_m >= 0");
  if (!(c.pitch_hz > 0) || !(c.roll_hz > 0) || !(c.heave_hz > 0) || c.pitch_hz > 20 ||
      c.roll_hz > 20 || c.heave_hz > 20)
    bad("pitch_hz, roll_hz and heave_hz must be in (0, 20]");
  if (!(c.damping_ratio > 0) || c.damping_ratio > 5) bad("damping_ratio must be in (0, 5]");
  if (!(std::abs(c.pitch_deg_per_mps2) <= 2) || !(std::abs(c.roll_deg_per_mps2) <= 2))
    bad("pitch_deg_per_mps2 and roll_deg_per_mps2 must be within [-2, 2]");
}

Trajectory vehicleSensorPoses(const Trajectory& path, const World& world,
                              const VehicleBodyConfig& c, double mount_height_m) {
  validate(c);
  Trajectory out = path;
  if (path.empty()) return out;
  const std::vector<double> v = speeds(path);
  RoadUnder u0 = roadUnder(world, path[0].T_world_body, mount_height_m, c);
  Axis heave{u0.heave, 0}, pitch{u0.pitch, 0}, roll{u0.roll, 0};
  out[0].T_world_body =
      sensorPose(path[0].T_world_body, heave.x, pitch.x, roll.x, mount_height_m, c);
  for (std::size_t i = 1; i < path.size(); ++i) {
    const double dt = path[i].t - path[i - 1].t;
    const RoadUnder u1 = roadUnder(world, path[i].T_world_body, mount_height_m, c);
    if (dt > 0) {
      const double ax = std::clamp((v[i] - v[i - 1]) / dt, -kMaxAccel_mps2, kMaxAccel_mps2);
      const double turn = std::remainder(
          yawOf(path[i].T_world_body) - yawOf(path[i - 1].T_world_body), 2 * std::numbers::pi);
      const double ay =
          std::clamp(0.5 * (v[i] + v[i - 1]) * turn / dt, -kMaxAccel_mps2, kMaxAccel_mps2);
      advance(heave, u0.heave, u1.heave, 0.0, dt, c.heave_hz, c.damping_ratio);
      advance(pitch, u0.pitch, u1.pitch, -c.pitch_deg_per_mps2 * kDeg * ax, dt, c.pitch_hz,
              c.damping_ratio);
      advance(roll, u0.roll, u1.roll, c.roll_deg_per_mps2 * kDeg * ay, dt, c.roll_hz,
              c.damping_ratio);
    }
    out[i].T_world_body =
        sensorPose(path[i].T_world_body, heave.x, pitch.x, roll.x, mount_height_m, c);
    u0 = u1;
  }
  return out;
}

}  // namespace slamroute::simulate
