#pragma once
// Paper §3.1 step 1 (Fig. 2b): intersection nodes from location traces with a hollow cylinder.
#include <vector>

#include "slamroute/core/Types.hpp"
#include "slamroute/roadgraph/Config.hpp"

namespace slamroute::roadgraph {

/// Trace points thinned to one point (the centroid) per voxel of `voxel_m`.
struct Downsampled {
  std::vector<Point3> points;
  std::vector<int> voxel_of;  ///< per input point, index into points
};
Downsampled downsample(const std::vector<Point3>& pts, double voxel_m);

struct IntersectionResult {
  std::vector<Point3> nodes;              ///< one per junction (robust centre)
  std::vector<int> branches;              ///< per node, branches seen at its centre
  std::vector<char> is_intersection;      ///< per (downsampled) point: >= min_branches clusters
  std::vector<int> node_of_point;         ///< per point, node id or -1
};

/// Runs the hollow-cylinder test on every point (TBB-parallel, deterministic), merges the
/// intersection points into nodes. `pts` are the downsampled trace points.
IntersectionResult detectIntersections(const std::vector<Point3>& pts, const NodeConfig& cfg);

/// Number of branches (clusters in the hollow cylinder around `centre`, see NodeConfig) of `pts`.
int countBranches(const std::vector<Point3>& pts, const Point3& centre, const NodeConfig& cfg);

}  // namespace slamroute::roadgraph
