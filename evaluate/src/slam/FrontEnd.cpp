#include "FrontEnd.hpp"

#include <limits>
#include <stdexcept>

#include "SlamClock.hpp"
#include "slamroute/evaluate/MotionChecks.hpp"
#include "slamroute/evaluate/RangeImage.hpp"

namespace slamroute::evaluate::slam {

Scan deskewed(const Scan& scan, const Pose3& sweep_motion, double sweep_s) {
  if (!scan.has_point_times || !(sweep_s > 0)) return scan;
  Scan out = scan;
  // A column's points share their firing time and come one after another: its motion is
  // worked out once, not per point.
  float motion_dt = std::numeric_limits<float>::quiet_NaN();
  Pose3 M = Pose3::Identity();
  for (ScanPoint& p : out.points) {
    if (!(p.dt == motion_dt)) {
      M = scaledMotion(sweep_motion, static_cast<double>(p.dt) / sweep_s);
      motion_dt = p.dt;
    }
    const Vec3 q = M * Vec3(p.x, p.y, p.z);
    p.x = static_cast<float>(q.x());
    p.y = static_cast<float>(q.y());
    p.z = static_cast<float>(q.z());
    p.dt = 0.0f;
  }
  out.has_point_times = false;
  return out;
}

Pose3 sweepMotionOfStep(const Pose3& T_from, const Pose3& T_to, double dt_s, double sweep_s) {
  if (!(dt_s > 0)) throw std::invalid_argument("sweep motion: the step's time must be positive");
  return scaledMotion(T_from.inverse() * T_to, sweep_s / dt_s);
}

bool enoughMatches(const AlignResult& r, const MappingConfig& c) {
  return r.edge_matches >= c.min_edge_features && r.plane_matches >= c.min_plane_features;
}

Cloud capped(Cloud c, int max_n) {
  if (max_n <= 0 || c.size() <= static_cast<std::size_t>(max_n)) return c;
  Cloud out;
  out.reserve(static_cast<std::size_t>(max_n));
  const double step = static_cast<double>(c.size()) / max_n;
  for (int i = 0; i < max_n; ++i) out.push_back(c[static_cast<std::size_t>(i * step)]);
  return out;
}

PreparedScan prepareScan(const Scan& scan, const LidarSpec& spec, const Config& cfg,
                         StageTimes& times) {
  PreparedScan p;
  double t0 = cpuNow();
  RangeImage img = projectScan(scan, spec, cfg);  // 1. range image
  times.projection += cpuSince(t0);
  if (img.valid_points == 0) {
    p.status = scan.points.empty() ? FrameStatus::Empty : FrameStatus::Invalid;
    return p;
  }
  if (img.valid_points < cfg.features.min_valid_points) {
    p.status = FrameStatus::Invalid;
    return p;
  }
  t0 = cpuNow();
  segmentGround(img, cfg);  // ground segmentation
  times.ground += cpuSince(t0);
  t0 = cpuNow();
  clusterRangeImage(img, cfg);  // range-image clustering
  times.clustering += cpuSince(t0);
  t0 = cpuNow();
  p.features = extractFeatures(img, cfg);  // 2. edge / planar features
  // Keyframes keep all voxel-filtered features (a dense local map); the scan-to-map source is
  // thinned to a fixed budget for speed.
  const MappingConfig& m = cfg.mapping;
  p.kf_edges = voxelFilter(p.features.less_sharp, m.edge_voxel_m);
  p.kf_planes = m.surf_voxel_m == cfg.features.less_flat_voxel_m
                    ? p.features.less_flat
                    : voxelFilter(p.features.less_flat, m.surf_voxel_m);
  p.src_edges = capped(p.kf_edges, m.max_source_edges);
  p.src_planes = capped(p.kf_planes, m.max_source_planes);
  times.features += cpuSince(t0);
  return p;
}

}  // namespace slamroute::evaluate::slam
