#pragma once
// LeGO-LOAM stage 2: edge and planar features by range curvature per ring, in sectors.
#include <Eigen/Core>
#include <vector>

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

}  // namespace slamroute::evaluate
