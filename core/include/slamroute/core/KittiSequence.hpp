#pragma once
// A KITTI odometry sequence folder as the evaluator reads it: SEQ/velodyne/NNNNNN.bin (with
// optional NNNNNN.time point times beside them), SEQ/times.txt, and as ground truth the optional
// SEQ/poses.txt (left camera poses, 3x4 row-major per scan) with SEQ/calib.txt's "Tr:" (velodyne
// -> camera), which bring the ground truth into the LiDAR frame.
#include <filesystem>
#include <memory>

#include "slamroute/core/Scan.hpp"
#include "slamroute/core/Trajectory.hpp"

namespace slamroute {

namespace kitti_files {
inline constexpr const char* kVelodyneDir = "velodyne";
inline constexpr const char* kTimes = "times.txt";
inline constexpr const char* kPoses = "poses.txt";
inline constexpr const char* kCalib = "calib.txt";
}  // namespace kitti_files

struct KittiSequence {
  std::unique_ptr<ScanSource> scans;
  /// LiDAR poses T_world_velodyne at the scans' times, the world being the first camera pose's
  /// frame turned into the LiDAR's axes (Tr^-1 * P_i * Tr); empty without poses.txt.
  Trajectory ground_truth;
};

/// Reads the calibration's "Tr:" line: T_camera_velodyne. Throws naming the file when the line
/// is missing or does not hold 12 numbers.
Pose3 readKittiCalibTr(const std::filesystem::path& calib);

/// Opens the sequence: checks that velodyne/ holds one .bin per line of times.txt and, when
/// poses.txt is there, that it has one pose per scan and calib.txt a Tr. Throws
/// std::invalid_argument naming the file and the problem. `spec`: the sensor (rings come from
/// the points' elevation).
KittiSequence readKittiSequence(const std::filesystem::path& dir, const LidarSpec& spec);

}  // namespace slamroute
