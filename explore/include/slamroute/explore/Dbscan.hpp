#pragma once
// DBSCAN (Ester et al. 1996) on plane points: the swarm seed paper's frontier segmentation.
// A point with at least min_points points (itself included) within eps is a core point;
// clusters are the core points joined through eps-neighbourhoods plus the border points they
// reach; the rest is noise (-1). Clusters are numbered in the order of their first point, so
// the same points give the same labels.
#include <vector>

#include "slamroute/core/Types.hpp"

namespace slamroute::explore {

struct DbscanResult {
  std::vector<int> label;  ///< per point: cluster in [0, clusters) or -1 (noise)
  int clusters = 0;
};

/// Throws std::invalid_argument when eps <= 0 or min_points < 1.
DbscanResult dbscan(const std::vector<Point2>& points, double eps, int min_points);

}  // namespace slamroute::explore
