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
/// max_m). Holds the grid and one float per point given, not the points. `mesh` must outlive it.
class MapAccuracyMeter {
 public:
  MapAccuracyMeter(const Mesh& mesh, double max_m, const Eigen::AlignedBox3f& bounds);
  void add(const Cloud& part);
  /// The distance of every point given so far, in the order given (until result() reorders them).
  const std::vector<float>& distances() const { return dist_; }
  MapAccuracy result();

 private:
  const Mesh& mesh_;
  double max_m_;
  Eigen::Vector2d lo_ = Eigen::Vector2d::Zero();
  int nx_ = 0, ny_ = 0;
  std::vector<std::uint32_t> cell_start_;  ///< triangles of cell c: faces_[cell_start_[c] .. cell_start_[c + 1])
  std::vector<std::uint32_t> cell_faces_;
  std::vector<std::uint64_t> seen_;  ///< per triangle: the last point (+1) it was measured for
  std::uint64_t counter_ = 0;
  std::vector<float> dist_;
  double sum_ = 0;
  std::size_t clamped_ = 0;
};

/// MapAccuracyMeter over a whole map at once.
MapAccuracy mapAccuracy(const Cloud& map, const Mesh& mesh, double max_m);

}  // namespace slamroute::evaluate
