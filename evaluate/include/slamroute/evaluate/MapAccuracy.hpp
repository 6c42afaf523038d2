#pragma once
// Map accuracy: distance of map points to the ground-truth world surface (world.ply).
#include <array>
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

/// Exact point-to-triangle distances through a 2D grid of triangles (cell = max_m), clamped at
/// max_m (points with no surface within max_m count as max_m).
MapAccuracy mapAccuracy(const Cloud& map, const Mesh& mesh, double max_m);

}  // namespace slamroute::evaluate
