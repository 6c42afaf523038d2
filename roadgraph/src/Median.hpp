#pragma once
// Median of a set of values (internal to roadgraph: vote groups, ring candidates).
#include <algorithm>
#include <cstddef>
#include <vector>

#include "slamroute/core/Types.hpp"

namespace slamroute::roadgraph::detail {

/// The upper median (element size/2 of the sorted values); 0 for none.
inline double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

/// Per-axis upper median of pts[members] (robust to a few far points); zero for none.
inline Point3 medianPoint(const std::vector<Point3>& pts, const std::vector<int>& members) {
  std::vector<double> xs, ys, zs;
  for (const int k : members) {
    const Point3& p = pts[static_cast<std::size_t>(k)];
    xs.push_back(p.x());
    ys.push_back(p.y());
    zs.push_back(p.z());
  }
  return {median(xs), median(ys), median(zs)};
}

}  // namespace slamroute::roadgraph::detail
