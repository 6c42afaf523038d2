#pragma once
// Output files of an evaluation: the map as binary PCD and the PNG plots.
#include <filesystem>

#include "slamroute/evaluate/CloudStore.hpp"
#include "slamroute/evaluate/Features.hpp"
#include "slamroute/evaluate/Metrics.hpp"

namespace slamroute::evaluate {

/// PCD v0.7, binary, fields x y z (float32); readable by PCL's pcl::io::loadPCDFile. Atomic.
void writePcd(const std::filesystem::path& path, const Cloud& cloud);

/// writePcd for a cloud that comes part by part (the SLAM map, tile by tile): the parts wait in
/// an unnamed file beside `path` (the header needs the point count) and commit() writes the
/// file atomically; without commit() nothing is left. Throws std::runtime_error naming the folder
/// or the file on a write error.
class PcdWriter {
 public:
  explicit PcdWriter(std::filesystem::path path);
  void add(const Cloud& part);
  void commit();
  std::size_t points() const { return points_; }

 private:
  std::filesystem::path path_;
  CloudStore parts_;
  std::size_t points_ = 0;
};
/// Top view: ground truth (green) and aligned estimate (red), same scale on both axes.
void plotTopView(const std::filesystem::path& path, const TrajectoryMetrics& m, int size_px);
/// ATE (after alignment) against distance travelled along the ground truth.
void plotErrorAlongDistance(const std::filesystem::path& path, const TrajectoryMetrics& m,
                            int size_px);

}  // namespace slamroute::evaluate
