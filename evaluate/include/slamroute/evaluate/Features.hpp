#pragma once
// LeGO-LOAM stage 2: edge and planar features by range curvature per ring, in sectors.
#include <Eigen/Core>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "slamroute/core/Types.hpp"
#include "slamroute/evaluate/Config.hpp"
#include "slamroute/evaluate/RangeImage.hpp"

namespace slamroute::evaluate {

using Cloud = std::vector<Eigen::Vector3f>;

struct FeatureSet {
  Cloud sharp;       ///< few sharpest edge points (non-ground), scan-to-scan source
  Cloud less_sharp;  ///< more edge points, scan-to-scan target and map
  Cloud flat;        ///< flattest ground points, scan-to-scan source
  Cloud less_flat;   ///< all planar points (voxel-filtered), target and map
  Cloud segmented;   ///< ground (strided) + clustered points: the map cloud
};

FeatureSet extractFeatures(const RangeImage& img, const Config& cfg);

/// Voxel-grid filter (centroid of each occupied voxel); voxel <= 0 returns the input.
Cloud voxelFilter(const Cloud& in, double voxel_m);
/// The voxel index along one axis of a coordinate `v`, `inv` = 1 / voxel size, exactly as
/// voxelFilter and VoxelMerger bin points.
inline std::int64_t voxelIndex(float v, float inv) {
  return static_cast<std::int64_t>(std::floor(v * inv));
}
/// The voxel of a point, 21 bits per axis (+-2^20 voxels around the origin), as voxelFilter and
/// VoxelMerger group points.
inline std::uint64_t voxelKey(const Eigen::Vector3f& p, float inv) {
  const auto q = [&](float v) {
    return static_cast<std::uint64_t>(voxelIndex(v, inv) + (1 << 20)) & 0x1FFFFF;
  };
  return (q(p.x()) << 42) | (q(p.y()) << 21) | q(p.z());
}
/// `c` moved by `T` (single precision, as the SLAM's clouds).
Cloud transformed(const Cloud& c, const Pose3& T);
/// The box around `b`'s eight corners moved by `T` as transformed() moves points (empty stays
/// empty). The points of a box moved by `T` lie in it up to float rounding.
Eigen::AlignedBox3f transformedBox(const Eigen::AlignedBox3f& b, const Pose3& T);

/// voxelFilter of clouds given one at a time: finish() returns, bit for bit, voxelFilter of their
/// concatenation, while holding only a buffer of chunk_points input points and one cell (24 bytes)
/// per occupied voxel. The whole map of a 75 km drive is ~400 M points before filtering; joined
/// and sorted at once they took 28 bytes each on top of the keyframes' own clouds.
class VoxelMerger {
 public:
  explicit VoxelMerger(double voxel_m, std::size_t chunk_points = std::size_t{1} << 24);
  void add(const Cloud& c);
  Cloud finish();

 private:
  struct Cell {
    std::uint64_t key;
    Eigen::Vector3f sum;
    std::uint32_t n;
  };
  void flush();
  double voxel_m_;
  std::size_t chunk_;
  Cloud buf_;
  std::vector<Cell> cells_;  ///< sorted by key; sums in input order
};

}  // namespace slamroute::evaluate
