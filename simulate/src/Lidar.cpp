#include "slamroute/simulate/Lidar.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "LidarNoise.hpp"
#include "WorldBoxes.hpp"
#include "WorldImpl.hpp"

namespace slamroute::simulate {

namespace {

/// Columns whose azimuth can see a box: an inclusive column interval (may wrap), or all.
struct BoxCull {
  detail::PreparedBox box;
  bool all = false;
  int c0 = 0, c1 = -1;  ///< c1 may exceed the column count (wrap)
};

/// Where the sensor is when a column fires, and when (after the sweep's start).
struct ColumnPose {
  Eigen::Matrix3f R = Eigen::Matrix3f::Identity();
  Eigen::Vector3f o = Eigen::Vector3f::Zero();
  Vec3 od = Vec3::Zero();
  float dt = 0;
  ColumnPose() = default;
  ColumnPose(const Pose3& T, float dt_s)
      : R(T.linear().cast<float>()),
        o(T.translation().cast<float>()),
        od(T.translation()),
        dt(dt_s) {}
};

/// Boxes in range of the sweep and the columns that can see each, from the sensor poses at the
/// sweep's start and end (the sensor turns and moves little within one sweep).
std::vector<BoxCull> cullBoxes(const std::vector<VehicleBox>& boxes, const Pose3& T_start,
                               const Pose3& T_end, double max_range, int columns) {
  std::vector<BoxCull> out;
  const Pose3 T_sw[2] = {T_start.inverse(), T_end.inverse()};
  const Vec3 o[2] = {T_start.translation(), T_end.translation()};
  for (const auto& b : boxes) {
    BoxCull bc;
    bc.box = detail::prepareBox(b);
    const double radius = bc.box.half.norm();
    const double dist = std::min((bc.box.c - o[0]).norm(), (bc.box.c - o[1]).norm());
    if (dist - radius > max_range) continue;
    if ((bc.box.c - o[0]).head<2>().norm() <= radius + 0.5 ||
        (bc.box.c - o[1]).head<2>().norm() <= radius + 0.5) {
      bc.all = true;
    } else {
      // azimuths of the 8 corners in the sensor frames, relative to the centre's azimuth at the
      // start
      const Vec3 cs = T_sw[0] * bc.box.c;
      const double a0 = std::atan2(cs.y(), cs.x());
      double lo = 0, hi = 0;
      bool all = false;
      for (int k = 0; k < 16; ++k) {
        const Eigen::Vector2d xy = bc.box.c.head<2>() +
                                   bc.box.u * bc.box.half.x() * ((k & 1) ? 1 : -1) +
                                   bc.box.v * bc.box.half.y() * ((k & 2) ? 1 : -1);
        const double z = bc.box.c.z() + bc.box.half.z() * ((k & 4) ? 1 : -1);
        const Vec3 p = T_sw[k >> 3] * Vec3(xy.x(), xy.y(), z);
        if (p.head<2>().norm() < 1e-6) all = true;
        double d = std::atan2(p.y(), p.x()) - a0;
        while (d > M_PI) d -= 2 * M_PI;
        while (d < -M_PI) d += 2 * M_PI;
        lo = std::min(lo, d);
        hi = std::max(hi, d);
      }
      if (all || hi - lo > M_PI) {
        bc.all = true;
      } else {
        const double step = 2 * M_PI / columns;
        bc.c0 = static_cast<int>(std::floor((a0 + lo) / step)) - 1;
        bc.c1 = static_cast<int>(std::ceil((a0 + hi) / step)) + 1;
        while (bc.c0 < 0) {
          bc.c0 += columns;
          bc.c1 += columns;
        }
      }
    }
    out.push_back(bc);
  }
  return out;
}

bool boxCoversColumn(const BoxCull& b, int c, int columns) {
  if (b.all) return true;
  return (c >= b.c0 && c <= b.c1) || (c + columns >= b.c0 && c + columns <= b.c1);
}

/// The return of lane k of a cast packet (ring r of column c, direction dir_s in the sensor
/// frame), with the traffic boxes, noise and dropout; false when there is none.
bool returnOf(const LidarSpec& spec, const LidarConfig& cfg, const World& world,
              const RTCRayHit16& rh, int k, const std::vector<BoxCull>& culled, int c, int r,
              const ColumnPose& pose, const Eigen::Vector3f& dir_s, std::uint64_t key,
              std::size_t idx, ScanPoint& p) {
  double range = std::numeric_limits<double>::infinity();
  Vec3 n = Vec3::UnitZ();
  SurfaceKind kind = SurfaceKind::Ground;
  const Vec3 d(rh.ray.dir_x[k], rh.ray.dir_y[k], rh.ray.dir_z[k]);
  if (rh.hit.geomID[k] != RTC_INVALID_GEOMETRY_ID) {
    range = rh.ray.tfar[k];
    n = Vec3(rh.hit.Ng_x[k], rh.hit.Ng_y[k], rh.hit.Ng_z[k]);
    kind = world.impl().mesh.kinds[rh.hit.primID[k]];
  }
  for (const auto& b : culled) {
    if (!boxCoversColumn(b, c, spec.horizontal_samples)) continue;
    double tb;
    Vec3 nb;
    if (detail::intersectBox(b.box, pose.od, d, std::min(range, spec.max_range_m), &tb, &nb)) {
      range = tb;
      n = nb;
      kind = SurfaceKind::Vehicle;
    }
  }
  if (!(range >= spec.min_range_m && range <= spec.max_range_m)) return false;
  detail::RayRandom rnd(key, idx);
  if (cfg.dropout_prob > 0 && rnd.uniform() < cfg.dropout_prob) return false;
  if (cfg.range_sigma_m > 0) range += cfg.range_sigma_m * rnd.normal();
  if (!(range >= spec.min_range_m && range <= spec.max_range_m)) return false;
  const double cosi = std::abs(n.normalized().dot(d));
  const Eigen::Vector3f q = dir_s * static_cast<float>(range);
  p.x = q.x();
  p.y = q.y();
  p.z = q.z();
  p.intensity = detail::reflectivity(kind) * static_cast<float>(cosi);
  p.ring = r;
  p.dt = pose.dt;
  return true;
}

}  // namespace

Lidar::Lidar(const LidarConfig& cfg, std::uint64_t seed)
    : cfg_(cfg), spec_(resolveLidarSpec(cfg)), seed_(seed) {
  if (!(cfg.range_sigma_m >= 0))
    throw std::invalid_argument("simulate.lidar: range_sigma_m must be >= 0");
  if (!(cfg.dropout_prob >= 0 && cfg.dropout_prob < 1))
    throw std::invalid_argument("simulate.lidar: dropout_prob must be in [0, 1)");
  if (!(cfg.sweep_period_s > 0 && cfg.sweep_period_s <= 1))
    throw std::invalid_argument("simulate.lidar: sweep_period_s must be in (0, 1]");
  for (int r = 0; r < spec_.channels; ++r) {
    cos_el_.push_back(static_cast<float>(std::cos(elevationRad(r))));
    sin_el_.push_back(static_cast<float>(std::sin(elevationRad(r))));
  }
  for (int c = 0; c < spec_.horizontal_samples; ++c) {
    cos_az_.push_back(static_cast<float>(std::cos(azimuthRad(c))));
    sin_az_.push_back(static_cast<float>(std::sin(azimuthRad(c))));
  }
}

double Lidar::elevationRad(int ring) const {
  const double up = spec_.vfov_up_deg, down = spec_.vfov_down_deg;
  const double deg =
      spec_.channels == 1 ? 0.5 * (up + down) : down + (up - down) * ring / (spec_.channels - 1);
  return deg * M_PI / 180.0;
}

double Lidar::azimuthRad(int column) const {
  return 2.0 * M_PI * column / spec_.horizontal_samples;
}

Scan Lidar::scan(const World& world, const Pose3& T_start, const Pose3& T_end,
                 const std::vector<VehicleBox>& boxes, std::size_t scan_index, double t) const {
  const int C = spec_.channels, H = spec_.horizontal_samples;
  const bool moving = cfg_.motion_distortion;
  const auto culled = cullBoxes(boxes, T_start, moving ? T_end : T_start, spec_.max_range_m, H);
  const RTCScene scene = world.impl().scene.scene();
  std::vector<ScanPoint> grid(static_cast<std::size_t>(C) * H);
  std::vector<unsigned char> valid(grid.size(), 0);
  const float tmax = static_cast<float>(spec_.max_range_m);
  const std::uint64_t key = detail::RayRandom::scanKey(seed_, scan_index);

  // Packets of one ring over 16 neighbouring columns: their rays are nearly parallel (a fraction
  // of a degree apart), which Embree traverses much faster than the rings of one column.
  tbb::parallel_for(tbb::blocked_range<int>(0, H, 64), [&](const tbb::blocked_range<int>& cols) {
    RTCIntersectContext ctx;
    alignas(64) RTCRayHit16 rh;
    alignas(64) int mask[16];
    ColumnPose pose[16];
    Eigen::Vector3f dir_s[16];
    for (int c0 = cols.begin(); c0 < cols.end(); c0 += 16) {
      const int n = std::min(16, cols.end() - c0);
      for (int k = 0; k < n; ++k) {
        // column c fires at its own moment of the sweep, from where the sensor is then
        const double f = moving ? static_cast<double>(c0 + k) / H : 0.0;
        pose[k] = ColumnPose(moving ? interpolatePose(T_start, T_end, f) : T_start,
                             static_cast<float>(f * cfg_.sweep_period_s));
      }
      for (int r = 0; r < C; ++r) {
        rtcInitIntersectContext(&ctx);
        ctx.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
        for (int k = 0; k < 16; ++k) {
          mask[k] = k < n ? -1 : 0;
          const int kk = std::min(k, n - 1), c = c0 + kk;
          dir_s[k] = Eigen::Vector3f(cos_el_[r] * cos_az_[c], cos_el_[r] * sin_az_[c], sin_el_[r]);
          detail::setRay16(rh, k, pose[kk].o, pose[kk].R * dir_s[k], tmax);
        }
        rtcIntersect16(mask, scene, &ctx, &rh);
        for (int k = 0; k < n; ++k) {
          const int c = c0 + k;
          const std::size_t idx = static_cast<std::size_t>(c) * C + r;
          valid[idx] = returnOf(spec_, cfg_, world, rh, k, culled, c, r, pose[k], dir_s[k], key,
                                idx, grid[idx]);
        }
      }
    }
  });
  Scan s;
  s.t = t;
  s.has_point_times = moving;
  s.points.reserve(grid.size());
  for (std::size_t i = 0; i < grid.size(); ++i)
    if (valid[i]) s.points.push_back(grid[i]);
  return s;
}

std::vector<Scan> Lidar::scanMany(const World& world, const std::vector<Pose3>& starts,
                                  const std::vector<Pose3>& ends,
                                  const std::vector<std::vector<VehicleBox>>& boxes,
                                  std::size_t first_index, const std::vector<double>& times) const {
  if (ends.size() != starts.size())
    throw std::invalid_argument("Lidar::scanMany: one end pose per start pose required");
  if (!boxes.empty() && boxes.size() != starts.size())
    throw std::invalid_argument("Lidar::scanMany: boxes must be empty or one entry per pose");
  if (!times.empty() && times.size() != starts.size())
    throw std::invalid_argument("Lidar::scanMany: times must be empty or one entry per pose");
  std::vector<Scan> out(starts.size());
  static const std::vector<VehicleBox> none;
  tbb::parallel_for(std::size_t{0}, starts.size(), [&](std::size_t k) {
    out[k] = scan(world, starts[k], ends[k], boxes.empty() ? none : boxes[k], first_index + k,
                  times.empty() ? 0.0 : times[k]);
  });
  return out;
}

Pose3 interpolatePose(const Pose3& a, const Pose3& b, double f) {
  const Eigen::Quaterniond qa(a.linear()), qb(b.linear());
  Pose3 T = Pose3::Identity();
  T.linear() = qa.slerp(f, qb).toRotationMatrix();
  T.translation() = a.translation() + f * (b.translation() - a.translation());
  return T;
}

Pose3 poseAtTime(const Trajectory& traj, std::size_t i, double t) {
  std::size_t j = i;
  while (j + 1 < traj.size() && traj[j + 1].t < t) ++j;
  if (j + 1 >= traj.size()) return traj.back().T_world_body;
  const double span = traj[j + 1].t - traj[j].t;
  const double f = span > 0 ? std::clamp((t - traj[j].t) / span, 0.0, 1.0) : 1.0;
  return interpolatePose(traj[j].T_world_body, traj[j + 1].T_world_body, f);
}

}  // namespace slamroute::simulate
