#pragma once
// Internals of the fleet merge shared by its files.
#include <cstddef>

#include "slamroute/evaluate/Fleet.hpp"

namespace slamroute::evaluate {

/// The scan whose time is nearest t.
std::size_t nearestScan(const ScanSource& scans, double t);
/// The trajectory's pose nearest in time to t (traj not empty, sorted by time).
Pose3 poseNearest(const Trajectory& traj, double t);
/// The scan's points in the sensor frame at the sweep's start, voxel-filtered. The points of a
/// spinning LiDAR are fired over the sweep while the car moves (a metre at 36 km/h); they are
/// moved back to the start with the motion of `poses` (the vehicle's estimate). Left as fired,
/// two vehicles passing each other in opposite directions match metres apart along the street.
Cloud bodyCloud(const ScanSource& scans, const Trajectory& poses, std::size_t index,
                double voxel_m);

/// Root-mean-square position error of each trajectory after ONE rigid alignment of all of them
/// onto their ground truths; the last entry is over all poses. `T_gt_est` receives the alignment.
std::vector<double> commonAteRmse(const std::vector<Trajectory>& estimates,
                                  const std::vector<Trajectory>& ground_truths, double max_dt_s,
                                  Pose3* T_gt_est = nullptr);

}  // namespace slamroute::evaluate
