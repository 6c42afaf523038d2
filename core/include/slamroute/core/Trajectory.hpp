#pragma once
// Timestamped pose sequences and their file formats (TUM, KITTI poses).
#include <filesystem>
#include <vector>

#include "slamroute/core/Types.hpp"

namespace slamroute {

struct StampedPose {
  double t = 0.0;  ///< seconds
  Pose3 T_world_body = Pose3::Identity();
};
using Trajectory = std::vector<StampedPose>;

/// Length of the path through the trajectory's positions [m].
double pathLength(const Trajectory& traj);

/// TUM: "t tx ty tz qx qy qz qw" per line, '#' comments. Throws naming file and line.
Trajectory readTum(const std::filesystem::path& path);
void writeTum(const std::filesystem::path& path, const Trajectory& traj);
/// KITTI poses: 12 numbers (3x4 row-major) per line; times are the line index * dt unless a
/// times file is given.
Trajectory readKittiPoses(const std::filesystem::path& path, double dt = 0.1);
void writeKittiPoses(const std::filesystem::path& path, const Trajectory& traj);
/// Reads TUM or KITTI by content (8 or 12 columns).
Trajectory readTrajectory(const std::filesystem::path& path);

}  // namespace slamroute
