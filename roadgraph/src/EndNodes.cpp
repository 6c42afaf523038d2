// Dead ends that nearly touch (paper §3.1 step 2, "dead ends get an end node"): two streets whose
// ends are within end_merge_m meet there, e.g. at a corner no survey vehicle drove round (each
// street then looks like a dead end; default city R0C5, R4C0).
#include <cmath>
#include <numeric>

#include "Streets.hpp"

namespace slamroute::roadgraph::detail {

/// Dead ends within `radius` of each other (and at one height) become one node at their mean:
/// two streets whose ends nearly touch meet there, e.g. at a corner no survey vehicle drove
/// round (each street then looks like a dead end). Streets left with both ends on one node are
/// dropped; end nodes that lose all streets stay and are dropped later as isolated.
void mergeNearbyEnds(std::vector<Point3>& nodes, const std::vector<char>& is_end, double radius,
                     double half_h, std::vector<Street>& streets, GraphBuildStats& st) {
  if (radius <= 0) return;
  std::vector<std::size_t> root(nodes.size());
  std::iota(root.begin(), root.end(), 0);
  auto find = [&](std::size_t i) {
    while (root[i] != i) i = root[i] = root[root[i]];
    return i;
  };
  for (std::size_t i = 0; i < nodes.size(); ++i)
    for (std::size_t j = i + 1; j < nodes.size(); ++j)
      if (is_end[i] && is_end[j] && (nodes[i] - nodes[j]).head<2>().norm() <= radius &&
          std::abs(nodes[i].z() - nodes[j].z()) <= half_h)
        root[find(j)] = find(i);
  std::vector<Point3> sum(nodes.size(), Point3::Zero());
  std::vector<int> cnt(nodes.size(), 0);
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (!is_end[i]) continue;
    sum[find(i)] += nodes[i];
    ++cnt[find(i)];
  }
  for (std::size_t i = 0; i < nodes.size(); ++i)
    if (is_end[i] && find(i) == i && cnt[i] > 1) {
      nodes[i] = sum[i] / cnt[i];
      st.dead_ends -= static_cast<std::size_t>(cnt[i] - 1);
      ++st.merged_end_pairs;
    }
  std::vector<Street> kept;
  for (auto& s : streets) {
    s.u = static_cast<int>(find(static_cast<std::size_t>(s.u)));
    s.v = static_cast<int>(find(static_cast<std::size_t>(s.v)));
    if (s.u == s.v) {
      ++st.dropped_fragments;
      continue;
    }
    kept.push_back(std::move(s));
  }
  streets = std::move(kept);
}

}  // namespace slamroute::roadgraph::detail
