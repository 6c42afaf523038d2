#pragma once
// The median of a measure's recent values, for estimates that a few outlying measurements must
// not move (WheelScale's stretches, TiltBias's closures).
#include <algorithm>
#include <deque>
#include <optional>
#include <vector>

namespace slamroute::evaluate::slam {

/// Appends `v` to `recent`, keeps its last `window` values and returns their median once there are
/// at least `min_count` (the upper one of an even count).
inline std::optional<double> pushRecentMedian(std::deque<double>& recent, double v, int window,
                                              int min_count) {
  recent.push_back(v);
  if (static_cast<int>(recent.size()) > window) recent.pop_front();
  if (static_cast<int>(recent.size()) < min_count) return std::nullopt;
  std::vector<double> r(recent.begin(), recent.end());
  std::nth_element(r.begin(), r.begin() + static_cast<long>(r.size() / 2), r.end());
  return r[r.size() / 2];
}

}  // namespace slamroute::evaluate::slam
