#pragma once
// LeGO-LOAM stage 1: range-image projection, ground segmentation, range-image clustering.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "slamroute/core/Scan.hpp"
#include "slamroute/evaluate/Config.hpp"

namespace slamroute::evaluate {

/// rows = rings (row 0 = lowest beam), cols = azimuth bins. Cells without a return have range 0.
struct RangeImage {
  static constexpr int kNoLabel = 0;
  static constexpr int kOutlier = -1;  ///< points of dropped (small) clusters
  int rows = 0, cols = 0;
  double vfov_down_rad = 0, vres_rad = 0, hres_rad = 0;
  std::vector<float> range;            ///< rows*cols, 0 = empty
  std::vector<Eigen::Vector3f> point;  ///< rows*cols, sensor frame
  std::vector<std::uint8_t> ground;    ///< rows*cols, 1 = ground
  std::vector<int> label;              ///< rows*cols, cluster id > 0, kOutlier, or kNoLabel
  int valid_points = 0;
  int clusters = 0;
  int idx(int r, int c) const { return r * cols + c; }
};

/// Projects a scan into the range image; NaN/inf and out-of-range points are dropped.
RangeImage projectScan(const Scan& scan, const LidarSpec& spec, const Config& cfg);
/// Marks ground cells: vertically adjacent points whose connecting slope is below
/// cfg.ground_angle_deg (LeGO-LOAM groundRemoval).
void segmentGround(RangeImage& img, const Config& cfg);
/// BFS clustering of non-ground cells (LeGO-LOAM labelComponents): neighbours join when the
/// angle beta = atan2(d2 sin a, d1 - d2 cos a) exceeds cfg.features.segment_theta_deg. Small
/// clusters are labelled kOutlier.
void clusterRangeImage(RangeImage& img, const Config& cfg);

}  // namespace slamroute::evaluate
