#include "DensestFirst.hpp"

#include <algorithm>
#include <numeric>

#include "Median.hpp"
#include "PointGrid.hpp"

namespace slamroute::roadgraph::detail {
namespace {

std::vector<int> densestFirstOrder(const PointGrid& grid, const std::vector<Point3>& pts,
                                   const DensestFirstParams& params) {
  std::vector<int> density(pts.size(), 0);
  for (std::size_t k = 0; k < pts.size(); ++k)
    grid.forEachNear(pts[k], params.density_radius_m, params.half_height_m,
                     [&](int) { ++density[k]; });
  std::vector<int> order(pts.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return density[static_cast<std::size_t>(a)] > density[static_cast<std::size_t>(b)];
  });
  return order;
}

/// The free points within the group radius of c, ascending.
std::vector<int> freePointsNear(const PointGrid& grid, const Point3& c,
                                const DensestFirstParams& params, const std::vector<char>& taken) {
  std::vector<int> m;
  grid.forEachNear(c, params.group_radius_m, params.half_height_m, [&](int k) {
    if (!taken[static_cast<std::size_t>(k)]) m.push_back(k);
  });
  std::sort(m.begin(), m.end());
  return m;
}

}  // namespace

std::vector<DensestFirstGroup> groupDensestFirst(const std::vector<Point3>& pts,
                                                 const DensestFirstParams& params) {
  const PointGrid grid(pts, std::max(params.group_radius_m, 1.0));
  std::vector<char> taken(pts.size(), 0);
  std::vector<DensestFirstGroup> groups;
  for (const int seed : densestFirstOrder(grid, pts, params)) {
    if (taken[static_cast<std::size_t>(seed)]) continue;
    DensestFirstGroup g;
    g.members = freePointsNear(grid, pts[static_cast<std::size_t>(seed)], params, taken);
    g.median = medianPoint(pts, g.members);
    if (params.regather_at_median) {
      g.members = freePointsNear(grid, g.median, params, taken);
      if (g.members.empty()) g.members.push_back(seed);
    }
    for (const int k : g.members) taken[static_cast<std::size_t>(k)] = 1;
    taken[static_cast<std::size_t>(seed)] = 1;
    groups.push_back(std::move(g));
  }
  return groups;
}

}  // namespace slamroute::roadgraph::detail
