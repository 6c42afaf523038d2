#pragma once
// Consistency of a drive folder's files before it is evaluated: the ground truth, the scans'
// times, the wheel odometry and the pose-to-edge table must be ordered in time and cover the same
// drive. A file cut short or shuffled otherwise gives plausible-looking but wrong metrics (the
// odometry's last sample held to the end, a third of the route evaluated, edges dropped).
#include <filesystem>

#include "slamroute/core/Scan.hpp"

namespace slamroute::evaluate {

/// Throws std::invalid_argument with one line naming the file that disagrees and how.
/// `scans` are the drive's scans (read from scans/ or regenerated from the ground truth).
void checkDriveFiles(const std::filesystem::path& drive, const ScanSource& scans);

}  // namespace slamroute::evaluate
