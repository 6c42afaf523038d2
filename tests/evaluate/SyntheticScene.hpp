#pragma once
// A tiny analytic ray caster for tests: a ground plane z = 0 plus axis-aligned boxes, scanned by
// an ideal spinning LiDAR. Points come back in the sensor frame with their ring index.
#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "slamroute/core/Scan.hpp"
#include "slamroute/core/Trajectory.hpp"
#include "slamroute/core/Types.hpp"

namespace slamroute::evaluate::test {

struct Box {
  Eigen::Vector3d lo, hi;
};

struct Scene {
  bool ground = true;
  std::vector<Box> boxes;

  /// Distance along unit ray (o, d) to the first surface, or +inf.
  double cast(const Eigen::Vector3d& o, const Eigen::Vector3d& d) const {
    double best = std::numeric_limits<double>::infinity();
    if (ground && d.z() < -1e-9) best = -o.z() / d.z();
    for (const Box& b : boxes) {
      double t0 = 0, t1 = best;
      bool hit = true;
      for (int a = 0; a < 3 && hit; ++a) {
        if (std::abs(d[a]) < 1e-12) {
          if (o[a] < b.lo[a] || o[a] > b.hi[a]) hit = false;
          continue;
        }
        double ta = (b.lo[a] - o[a]) / d[a], tb = (b.hi[a] - o[a]) / d[a];
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
        if (t0 > t1) hit = false;
      }
      if (hit && t0 > 1e-6 && t0 < best) best = t0;
    }
    return best;
  }
};

/// A spinning LiDAR with `channels` rings (the default vertical field) and 900 columns (0.4 deg):
/// coarse enough for a test to ray-cast a few hundred scans.
inline LidarSpec coarseLidar(int channels) {
  LidarSpec s;
  s.channels = channels;
  s.horizontal_samples = 900;
  return s;
}

/// Scans the scene from T_world_sensor. noise_m: Gaussian range noise (seeded).
inline Scan scanScene(const Scene& scene, const Pose3& T_world_sensor, const LidarSpec& spec,
                      double t = 0.0, double noise_m = 0.0, std::uint64_t seed = 1) {
  Scan s;
  s.t = t;
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> nd(0.0, 1.0);
  const double vstep = (spec.vfov_up_deg - spec.vfov_down_deg) / (spec.channels - 1);
  const Eigen::Matrix3d R = T_world_sensor.rotation();
  const Eigen::Vector3d o = T_world_sensor.translation();
  for (int r = 0; r < spec.channels; ++r) {
    const double el = (spec.vfov_down_deg + r * vstep) * std::numbers::pi / 180.0;
    for (int c = 0; c < spec.horizontal_samples; ++c) {
      const double az =
          -std::numbers::pi + (c + 0.5) * 2.0 * std::numbers::pi / spec.horizontal_samples;
      const Eigen::Vector3d ds(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az),
                               std::sin(el));
      double range = scene.cast(o, R * ds);
      if (!(range <= spec.max_range_m)) continue;
      if (noise_m > 0) range += noise_m * nd(rng);
      if (range < spec.min_range_m) continue;
      const Eigen::Vector3d p = range * ds;
      s.points.push_back({static_cast<float>(p.x()), static_cast<float>(p.y()),
                          static_cast<float>(p.z()), 0.0f, r});
    }
  }
  return s;
}

/// A street canyon around the origin: building blocks on both sides of x-running and y-running
/// streets, plus poles, so every direction is constrained.
inline Scene cityScene(double extent_m = 120.0) {
  Scene s;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  // blocks on a 40 m grid with 14 m wide streets along x = k*40 and y = k*40
  for (double bx = -extent_m; bx < extent_m; bx += 40.0) {
    for (double by = -extent_m; by < extent_m; by += 40.0) {
      const double x0 = bx + 7.0, y0 = by + 7.0;
      // split the block into 2-3 buildings with different heights and setbacks
      const int nb = 2 + static_cast<int>(u(rng) * 2);
      const double w = 26.0 / nb;
      for (int i = 0; i < nb; ++i) {
        const double sx = x0 + i * w + 0.5, sb = u(rng) * 2.0;
        s.boxes.push_back(
            {{sx + sb * 0.3, y0 + sb, 0.0}, {sx + w - 1.0, y0 + 26.0 - sb, 6.0 + 20.0 * u(rng)}});
      }
      // a pole at the block corner
      s.boxes.push_back({{x0 - 2.0, y0 - 2.0, 0.0}, {x0 - 1.7, y0 - 1.7, 5.0}});
    }
  }
  return s;
}

/// Boxes of random footprint (2-16 m) and height (1-21 m) scattered over 200 x 200 m around
/// the origin, none within 9 m of it: an irregular place, a different one per seed.
inline Scene scatteredScene(std::uint64_t seed, int boxes = 70) {
  Scene s;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  while (static_cast<int>(s.boxes.size()) < boxes) {
    const double cx = -100 + 200 * u(rng), cy = -100 + 200 * u(rng);
    const double w = 2 + 14 * u(rng), d = 2 + 14 * u(rng), h = 1 + 20 * u(rng);
    if (std::hypot(cx, cy) < 9.0 + 0.5 * std::hypot(w, d)) continue;
    s.boxes.push_back({{cx - w / 2, cy - d / 2, 0.0}, {cx + w / 2, cy + d / 2, h}});
  }
  return s;
}

inline Pose3 poseXYZYaw(double x, double y, double z, double yaw_rad) {
  Pose3 T = Pose3::Identity();
  T.linear() = Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  T.translation() = Eigen::Vector3d(x, y, z);
  return T;
}

/// Sensor pose at arc length s on a rounded square loop: corners (0,0)..(side,side), corner radius
/// r, counter-clockwise, heading along the path, height 1.8 m.
inline Pose3 roundedLoopPose(double s, double side, double r) {
  const double straight = side - 2 * r, quarter = 0.5 * std::numbers::pi * r;
  const double per = 4 * (straight + quarter);
  s = std::fmod(std::fmod(s, per) + per, per);
  const int k = static_cast<int>(s / (straight + quarter));
  double u = s - k * (straight + quarter);
  // local frame of side k: start point and heading
  const double heading0 = k * 0.5 * std::numbers::pi;
  const Eigen::Vector2d starts[4] = {{r, 0}, {side, r}, {side - r, side}, {0, side - r}};
  const Eigen::Vector2d dir(std::cos(heading0), std::sin(heading0));
  const Eigen::Vector2d left(-dir.y(), dir.x());
  Eigen::Vector2d p;
  double yaw = heading0;
  if (u <= straight) {
    p = starts[k] + u * dir;
  } else {
    const double a = (u - straight) / r;  // turned angle
    const Eigen::Vector2d c = starts[k] + straight * dir + r * left;
    p = c - r * left * std::cos(a) + r * dir * std::sin(a);
    yaw += a;
  }
  return poseXYZYaw(p.x(), p.y(), 1.8, yaw);
}

/// Noisy 32 x 900 scans along the rounded square loop (side 80 m, corner radius 10 m) through
/// cityScene(80), 1.5 m per scan, from arc length start_m on.
class LoopScanSource : public ScanSource {
 public:
  explicit LoopScanSource(double start_m = 0.0, std::size_t scans = 215)
      : scene_(cityScene(80.0)), start_m_(start_m), scans_(scans) {
    spec_.channels = 32;
    spec_.horizontal_samples = 900;
  }
  std::size_t size() const override { return scans_; }
  double time(std::size_t i) const override { return 0.1 * static_cast<double>(i); }
  Pose3 pose(std::size_t i) const {
    return roundedLoopPose(start_m_ + 1.5 * static_cast<double>(i), 80.0, 10.0);
  }
  Scan scan(std::size_t i) const override {
    return scanScene(scene_, pose(i), spec_, time(i), 0.03, 100 + i);
  }
  LidarSpec spec() const override { return spec_; }
  Trajectory groundTruth() const {
    Trajectory gt;
    for (std::size_t i = 0; i < size(); ++i) gt.push_back({time(i), pose(i)});
    return gt;
  }

 private:
  Scene scene_;
  double start_m_;
  std::size_t scans_;
  LidarSpec spec_;
};

}  // namespace slamroute::evaluate::test
