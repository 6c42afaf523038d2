#pragma once
// Greedy grouping of points around their densest places (internal to roadgraph): the centre votes
// of junctions (Intersections.cpp) and the circle centres of roundabouts (Roundabouts.cpp).
// Unlike connected components it splits a chain of dense places closer together than the
// grouping radius into several groups.
#include <vector>

#include "slamroute/core/Types.hpp"

namespace slamroute::roadgraph::detail {

struct DensestFirstParams {
  double density_radius_m = 0.0;  ///< a point's density: points within this of it [m]
  double group_radius_m = 0.0;    ///< a seed takes the free points within this of it [m]
  double half_height_m = 0.0;     ///< points farther apart in z never group [m]
  /// Take the free points within group_radius_m of the median of the seed's group instead (a
  /// seed on the edge of a place would otherwise leave its far side for a group of its own).
  bool regather_at_median = false;
};

struct DensestFirstGroup {
  Point3 median = Point3::Zero();  ///< per-axis median of the points gathered at the seed
  std::vector<int> members;        ///< indices into the points, ascending
};

/// Seeds in order of density (most points within density_radius_m first, ties by index); each
/// seed not yet taken starts a group of the free points within group_radius_m.
std::vector<DensestFirstGroup> groupDensestFirst(const std::vector<Point3>& pts,
                                                 const DensestFirstParams& params);

}  // namespace slamroute::roadgraph::detail
