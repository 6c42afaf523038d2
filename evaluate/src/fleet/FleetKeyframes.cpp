// The merge keyframes of one vehicle: its estimate every keyframe_spacing_m, each with its scan.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "../slam/FrontEnd.hpp"
#include "FleetInternal.hpp"
#include "slamroute/evaluate/MotionChecks.hpp"

namespace slamroute::evaluate {

std::size_t nearestScan(const ScanSource& scans, double t) {
  std::size_t lo = 0, hi = scans.size();
  while (hi - lo > 1) {
    const std::size_t mid = (lo + hi) / 2;
    (scans.time(mid) <= t ? lo : hi) = mid;
  }
  if (lo + 1 < scans.size() && std::abs(scans.time(lo + 1) - t) < std::abs(scans.time(lo) - t))
    return lo + 1;
  return lo;
}

Pose3 poseNearest(const Trajectory& traj, double t) {
  const auto it = std::lower_bound(traj.begin(), traj.end(), t,
                                   [](const StampedPose& p, double v) { return p.t < v; });
  if (it == traj.end()) return traj.back().T_world_body;
  if (it == traj.begin() || std::abs(it->t - t) <= std::abs(std::prev(it)->t - t))
    return it->T_world_body;
  return std::prev(it)->T_world_body;
}

std::vector<FleetKeyframe> fleetKeyframes(const Trajectory& estimate, const ScanSource& scans,
                                          double spacing_m) {
  if (estimate.empty() || scans.size() == 0)
    throw std::invalid_argument("fleet merge: a vehicle has no estimate or no scans");
  std::vector<FleetKeyframe> kfs;
  double since = spacing_m, driven = 0.0;  // the first pose is a keyframe
  for (std::size_t i = 0; i < estimate.size(); ++i) {
    if (i > 0) {
      const double step =
          (estimate[i].T_world_body.translation() - estimate[i - 1].T_world_body.translation())
              .norm();
      since += step;
      driven += step;
    }
    if (since < spacing_m && i + 1 < estimate.size()) continue;
    since = 0.0;
    kfs.push_back(
        {estimate[i].t, nearestScan(scans, estimate[i].t), estimate[i].T_world_body, driven});
  }
  return kfs;
}

namespace {

/// A sweep lasts until the next scan starts (the last one as long as the one before it) [s].
double sweepSeconds(const ScanSource& scans, std::size_t i) {
  if (i + 1 < scans.size()) return scans.time(i + 1) - scans.time(i);
  return i > 0 ? scans.time(i) - scans.time(i - 1) : 0.0;
}

/// The body's motion over sweep_s from time t: the step between the two poses around t, scaled.
Pose3 motionOver(const Trajectory& poses, double t, double sweep_s) {
  if (poses.size() < 2) return Pose3::Identity();
  auto next = std::upper_bound(poses.begin(), poses.end(), t,
                               [](double v, const StampedPose& p) { return v < p.t; });
  if (next == poses.end()) --next;
  if (next == poses.begin()) ++next;
  const auto prev = std::prev(next);
  const double span_s = next->t - prev->t;
  if (!(span_s > 0.0)) return Pose3::Identity();
  return scaledMotion(prev->T_world_body.inverse() * next->T_world_body, sweep_s / span_s);
}

}  // namespace

Cloud bodyCloud(const ScanSource& scans, const Trajectory& poses, std::size_t index,
                double voxel_m) {
  const Scan raw = scans.scan(index);
  const double sweep_s = sweepSeconds(scans, index);
  const Scan scan = slam::deskewed(raw, motionOver(poses, raw.t, sweep_s), sweep_s);
  Cloud c;
  c.reserve(scan.points.size());
  for (const auto& p : scan.points) c.emplace_back(p.x, p.y, p.z);
  return voxelFilter(c, voxel_m);
}

}  // namespace slamroute::evaluate
