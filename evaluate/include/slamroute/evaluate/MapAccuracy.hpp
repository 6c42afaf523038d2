#pragma once
// Map accuracy: distance of map points to the ground-truth world surface (world.ply).
#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "slamroute/evaluate/Features.hpp"

namespace slamroute::evaluate {

struct Mesh {
  std::vector<Eigen::Vector3f> vertices;
  std::vector<std::array<int, 3>> faces;  ///< polygons are fanned into triangles
};

/// Reads a PLY triangle mesh (binary little-endian or ASCII). Throws naming the file.
Mesh readPly(const std::filesystem::path& path);

struct MapAccuracy {
  int points = 0;
  double mean_m = 0, median_m = 0, p95_m = 0;
  double clamped_share = 0;  ///< share of points farther than the clamp distance
};

/// Map accuracy of a map given part by part (the SLAM's map comes tile by tile, MapTiles.hpp):
/// exact point-to-triangle distances through a 2D grid of the triangles over `bounds` (cell =
/// max_m), clamped at max_m (points with no surface within max_m, or outside `bounds`, count as
/// max_m). The median and p95 come from a histogram of 0.1 mm bins (to within 0.05 mm; a
/// clamped quantile is max_m exactly), so the meter holds the grid and the histogram, nothing per
/// point: a 75 km map has 40 M points. `mesh` must outlive it.
class MapAccuracyMeter {
 public:
  static constexpr double kBinM = 1e-4;  ///< histogram bin [m]
  MapAccuracyMeter(const Mesh& mesh, double max_m, const Eigen::AlignedBox3f& bounds);
  /// Measures `part`; its points' distances are appended to `dist_m` when given.
  void add(const Cloud& part, std::vector<float>* dist_m = nullptr);
  MapAccuracy result() const;

 private:
  double quantile(std::uint64_t rank) const;  ///< the rank-th smallest distance (0-based)
  const Mesh& mesh_;
  double max_m_;
  Eigen::Vector2d lo_ = Eigen::Vector2d::Zero();
  int nx_ = 0, ny_ = 0;
  std::vector<std::uint32_t>
      cell_start_;  ///< triangles of cell c: faces_[cell_start_[c] .. cell_start_[c + 1])
  std::vector<std::uint32_t> cell_faces_;
  std::vector<std::uint64_t> seen_;  ///< per triangle: the last point (+1) it was measured for
  std::uint64_t counter_ = 0;        ///< points measured
  std::vector<std::uint64_t> hist_;  ///< distances below max_m in kBinM bins
  double sum_ = 0;
  std::uint64_t clamped_ = 0;
};

/// MapAccuracyMeter over a whole map at once.
MapAccuracy mapAccuracy(const Cloud& map, const Mesh& mesh, double max_m);

}  // namespace slamroute::evaluate
