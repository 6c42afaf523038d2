// The merge keyframes of one vehicle: its estimate every keyframe_spacing_m, each with its scan.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "FleetInternal.hpp"

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

Cloud bodyCloud(const ScanSource& scans, std::size_t index, double voxel_m) {
  const Scan scan = scans.scan(index);
  Cloud c;
  c.reserve(scan.points.size());
  for (const auto& p : scan.points) c.emplace_back(p.x, p.y, p.z);
  return voxelFilter(c, voxel_m);
}

}  // namespace slamroute::evaluate
