#pragma once
// Spatial hash grid over the horizontal (x, y) coordinates of a point set. Queries visit only the
// cells a disk overlaps, so a radius query costs O(points nearby), which keeps the hollow-cylinder
// test of every trace point near-linear in the number of points.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

#include "slamroute/core/Types.hpp"
#include "slamroute/core/UnionFind.hpp"

namespace slamroute::roadgraph::detail {

class PointGrid {
 public:
  PointGrid(const std::vector<Point3>& pts, double cell_m) : pts_(pts), cell_(cell_m) {
    std::vector<std::pair<std::uint64_t, int>> keyed;
    keyed.reserve(pts.size());
    for (int i = 0; i < static_cast<int>(pts.size()); ++i)
      keyed.emplace_back(key(cellOf(pts[i].x()), cellOf(pts[i].y())), i);
    std::sort(keyed.begin(), keyed.end());
    order_.reserve(keyed.size());
    cells_.reserve(keyed.size() / 4 + 16);
    for (std::size_t i = 0; i < keyed.size(); ++i) {
      if (i == 0 || keyed[i].first != keyed[i - 1].first)
        cells_[keyed[i].first] = {static_cast<int>(i), static_cast<int>(i)};
      cells_[keyed[i].first].second = static_cast<int>(i) + 1;
      order_.push_back(keyed[i].second);
    }
  }

  /// Precomputes, for every point, the other points within 3D distance tol (the pairs the
  /// hollow-cylinder test clusters). Each point lies in the rings of hundreds of others; finding
  /// its close pairs once instead of in every ring makes that test ~2x faster (bench/RESULTS.md).
  void linkWithin(double tol) {
    link_tol_ = tol;
    link_start_.assign(pts_.size() + 1, 0);
    links_.clear();
    const double tol2 = tol * tol;
    for (std::size_t i = 0; i < pts_.size(); ++i) {
      const Point3& p = pts_[i];
      forEachNear(p, tol, tol, [&](int j) {
        if (static_cast<std::size_t>(j) != i &&
            (pts_[static_cast<std::size_t>(j)] - p).squaredNorm() <= tol2)
          links_.push_back(j);
      });
      link_start_[i + 1] = links_.size();
    }
  }
  /// Tolerance of linkWithin (0 before it ran).
  double linkTolerance() const { return link_tol_; }
  /// Calls f(j) for every point j linked to point i by linkWithin.
  template <class F>
  void forEachLinked(int i, F&& f) const {
    const auto k = static_cast<std::size_t>(i);
    for (std::size_t m = link_start_[k]; m < link_start_[k + 1]; ++m) f(links_[m]);
  }

  /// Calls f(index) for every point within horizontal distance r of c and |dz| <= half_height.
  template <class F>
  void forEachNear(const Point3& c, double r, double half_height, F&& f) const {
    const long x0 = cellOf(c.x() - r), x1 = cellOf(c.x() + r);
    const long y0 = cellOf(c.y() - r), y1 = cellOf(c.y() + r);
    const double r2 = r * r;
    for (long ix = x0; ix <= x1; ++ix)
      for (long iy = y0; iy <= y1; ++iy) {
        const auto it = cells_.find(key(ix, iy));
        if (it == cells_.end()) continue;
        for (int k = it->second.first; k < it->second.second; ++k) {
          const int i = order_[static_cast<std::size_t>(k)];
          const Point3& p = pts_[static_cast<std::size_t>(i)];
          const double dx = p.x() - c.x(), dy = p.y() - c.y();
          if (dx * dx + dy * dy <= r2 && std::abs(p.z() - c.z()) <= half_height) f(i);
        }
      }
  }

 private:
  long cellOf(double v) const { return static_cast<long>(std::floor(v / cell_)); }
  static std::uint64_t key(long ix, long iy) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(ix)) << 32) |
           static_cast<std::uint32_t>(iy);
  }
  const std::vector<Point3>& pts_;
  double cell_;
  std::vector<int> order_;
  std::unordered_map<std::uint64_t, std::pair<int, int>> cells_;
  double link_tol_ = 0.0;
  std::vector<std::size_t> link_start_;
  std::vector<int> links_;
};

using slamroute::UnionFind;

/// Connected components of `pts` linking points closer than tol (3D). Returns a label per point
/// (labels 0..n-1 in order of first appearance) and writes the component count.
std::vector<int> euclideanComponents(const std::vector<Point3>& pts, double tol, int* count);

}  // namespace slamroute::roadgraph::detail
