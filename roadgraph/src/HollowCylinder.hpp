#pragma once
// Internal to roadgraph: the hollow-cylinder test of one point (paper §3.1 step 1, Fig. 2b) and
// the least-squares crossing of the branches it sees (the centre votes). See Intersections.cpp.
#include <Eigen/Core>
#include <vector>

#include "PointGrid.hpp"
#include "slamroute/core/Types.hpp"
#include "slamroute/roadgraph/Config.hpp"

namespace slamroute::roadgraph::detail {

/// Reusable buffers of one hollow-cylinder test (one per thread). Per point in the cylinder:
/// local (its index in the whole set), rel (its offset from the centre), in_annulus; per
/// annulus cluster (indexed by its root point): the sums below.
struct Scratch {
  std::vector<int> local;
  std::vector<Point3> rel;
  std::vector<char> in_annulus;
  std::vector<int> local_of;  // per point of the whole set: its index in `local`, else -1
  std::vector<int> cluster_points;
  std::vector<double> radius_min, radius_max, bearing_x, bearing_y;
  std::vector<char> reaches_centre;                  // linked to the point inside the outer disk
  std::vector<Eigen::Matrix<double, 5, 1>> moments;  // per cluster: sum x, y, xx, xy, yy
  std::vector<int> branch_of_cluster;
  UnionFind disk_sets, annulus_sets, branch_sets;
  std::vector<std::vector<int>> members;
};

/// Hollow-cylinder test around c (grid linked at cfg.cluster_tolerance_m): returns the number of
/// branches; with `members`, their points (indices into pts); with `coverage_deg`, the range of
/// bearings [deg] the outer half of the ring holds points in (64 sectors).
int branchesAt(const PointGrid& grid, const std::vector<Point3>& pts, const Point3& c,
               const NodeConfig& cfg, Scratch& s, std::vector<std::vector<int>>* members,
               double* coverage_deg = nullptr);

/// Least-squares crossing (horizontal) of the centre lines of `members` (one point list per
/// branch) as seen from `c`; `axes` (optional): travel axes per point. False when the lines are
/// close to parallel (no stable crossing).
bool crossingOf(const std::vector<Point3>& pts, const std::vector<std::vector<int>>& members,
                const Point3& c, const NodeConfig& cfg, const std::vector<Eigen::Vector2d>* axes,
                Eigen::Vector2d& x);

/// Iterated crossing of the branches seen from `start` (at most `iters` re-evaluations, each
/// moving < max_jump from start). Returns false when no crossing could be formed; `out` holds the
/// last accepted position (start when none), z unchanged.
bool crossingFrom(const PointGrid& grid, const std::vector<Point3>& pts,
                  const std::vector<Eigen::Vector2d>* axes, const Point3& start,
                  const NodeConfig& cfg, Scratch& s, int iters, double max_jump, Point3& out);

}  // namespace slamroute::roadgraph::detail
