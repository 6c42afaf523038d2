#pragma once
// Output files of an evaluation: the map as binary PCD and the PNG plots.
#include <filesystem>

#include "slamroute/evaluate/Features.hpp"
#include "slamroute/evaluate/Metrics.hpp"

namespace slamroute::evaluate {

/// PCD v0.7, binary, fields x y z (float32); readable by PCL's pcl::io::loadPCDFile. Atomic.
void writePcd(const std::filesystem::path& path, const Cloud& cloud);
/// Top view: ground truth (green) and aligned estimate (red), same scale on both axes.
void plotTopView(const std::filesystem::path& path, const TrajectoryMetrics& m, int size_px);
/// ATE (after alignment) against distance travelled along the ground truth.
void plotErrorAlongDistance(const std::filesystem::path& path, const TrajectoryMetrics& m,
                            int size_px);

}  // namespace slamroute::evaluate
