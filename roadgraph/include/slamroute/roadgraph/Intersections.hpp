#pragma once
// Paper §3.1 step 1 (Fig. 2b): intersection nodes from location traces with a hollow cylinder.
#include <Eigen/Core>
#include <vector>

#include "slamroute/core/Types.hpp"
#include "slamroute/roadgraph/Config.hpp"
#include "slamroute/roadgraph/Traces.hpp"

namespace slamroute::roadgraph {

/// Trace points thinned to one point (the centroid) per voxel of `voxel_m`.
struct Downsampled {
  std::vector<Point3> points;
  std::vector<int> voxel_of;  ///< per input point, index into points
  /// Per voxel, the sum of its points' travel axes as doubled-angle vectors
  /// (cos 2a, sin 2a): opposite directions of travel add up. Empty without `travel`.
  std::vector<Eigen::Vector2d> axes;
};
/// `travel` (optional, one per point): direction of travel, zero when unknown.
Downsampled downsample(const std::vector<Point3>& pts, double voxel_m,
                       const std::vector<Vec3>* travel = nullptr);

/// Direction of travel of every trace point: from the vehicle's position `span_m` behind to
/// `span_m` ahead along its own trace (breaks at time gaps > max_gap_s); zero when the vehicle
/// did not move that far. Robust to GPS noise across the road.
/// `order`: byVehicleThenTime(traces), when the caller has it already.
std::vector<Vec3> travelDirections(const Traces& traces, const std::vector<std::size_t>& order,
                                   double span_m, double max_gap_s);
std::vector<Vec3> travelDirections(const Traces& traces, double span_m, double max_gap_s);

struct IntersectionResult {
  std::vector<Point3> nodes;          ///< one per junction (robust centre)
  std::vector<int> branches;          ///< per node, branches seen at its centre
  std::vector<char> is_intersection;  ///< per (downsampled) point: >= min_branches clusters
  std::vector<int> node_of_point;     ///< per point, node id or -1
};

/// Runs the hollow-cylinder test on every point (TBB-parallel, deterministic), merges the
/// intersection points into nodes. `pts` are the downsampled trace points.
/// `axes` (optional, Downsampled::axes): travel axes per point; with them an arm's direction is
/// the vehicles' mean axis, otherwise the principal axis of its points.
IntersectionResult detectIntersections(const std::vector<Point3>& pts, const NodeConfig& cfg,
                                       const std::vector<Eigen::Vector2d>* axes = nullptr);

/// Number of branches (clusters in the hollow cylinder around `centre`, see NodeConfig) of `pts`.
int countBranches(const std::vector<Point3>& pts, const Point3& centre, const NodeConfig& cfg);

}  // namespace slamroute::roadgraph
