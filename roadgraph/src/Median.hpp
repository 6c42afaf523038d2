#pragma once
// Median of a set of values (internal to roadgraph: vote groups, ring candidates).
#include <algorithm>
#include <cstddef>
#include <vector>

namespace slamroute::roadgraph::detail {

/// The upper median (element size/2 of the sorted values); 0 for none.
inline double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

}  // namespace slamroute::roadgraph::detail
