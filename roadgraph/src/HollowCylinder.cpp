// The hollow-cylinder test of one point (paper §3.1 step 1): Euclidean clusters of the trace
// points in the ring around it, grouped into branches. The choices are documented in
// Intersections.cpp.
#include "HollowCylinder.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <stdexcept>

namespace slamroute::roadgraph::detail {

/// Hollow-cylinder test around c: the branches (annulus clusters) as lists of point indices when
/// `members` is given; returns their number.
int branchesAt(const PointGrid& grid, const std::vector<Point3>& pts, const Point3& c,
               const NodeConfig& cfg, Scratch& s, std::vector<std::vector<int>>* members,
               double* coverage_deg) {
  const double R = cfg.outer_radius_m, r_in2 = cfg.inner_radius_m * cfg.inner_radius_m;
  const double tol = cfg.cluster_tolerance_m, tol2 = tol * tol;
  s.local.clear();
  s.rel.clear();
  s.in_ann.clear();
  grid.forEachNear(c, R, 0.5 * cfg.height_m, [&](int i) {
    const Point3 d = pts[static_cast<std::size_t>(i)] - c;
    const bool ann = d.x() * d.x() + d.y() * d.y() >= r_in2;
    if (!ann && !cfg.require_connected) return;  // inner points only matter for connectivity
    s.local.push_back(i);
    s.rel.push_back(d);
    s.in_ann.push_back(ann ? 1 : 0);
  });
  const int n = static_cast<int>(s.local.size());
  if (coverage_deg) *coverage_deg = 0.0;
  if (n == 0) return 0;
  if (grid.linkTolerance() != tol)
    throw std::logic_error("branchesAt: the point grid is not linked at cluster_tolerance_m");
  if (s.local_of.size() != pts.size()) s.local_of.assign(pts.size(), -1);
  for (int i = 0; i < n; ++i)
    s.local_of[static_cast<std::size_t>(s.local[static_cast<std::size_t>(i)])] = i;
  s.disk.reset(static_cast<std::size_t>(n));
  s.ann.reset(static_cast<std::size_t>(n));
  int self = -1;
  double self_d2 = tol2;
  for (int i = 0; i < n; ++i) {
    const auto& di = s.rel[static_cast<std::size_t>(i)];
    if (di.squaredNorm() <= self_d2) {
      self_d2 = di.squaredNorm();
      self = i;
    }
    // Pairs closer than tol, both inside the cylinder (unite keeps the smallest index as root,
    // so the order of the pairs does not matter).
    grid.forEachLinked(s.local[static_cast<std::size_t>(i)], [&](int g) {
      const int j = s.local_of[static_cast<std::size_t>(g)];
      if (j <= i) return;
      s.disk.unite(i, j);
      if (s.in_ann[static_cast<std::size_t>(i)] && s.in_ann[static_cast<std::size_t>(j)])
        s.ann.unite(i, j);
    });
  }
  for (int i : s.local) s.local_of[static_cast<std::size_t>(i)] = -1;
  s.cnt.assign(static_cast<std::size_t>(n), 0);
  s.conn.assign(static_cast<std::size_t>(n), cfg.require_connected ? 0 : 1);
  s.rmin.assign(static_cast<std::size_t>(n), 1e300);
  s.rmax.assign(static_cast<std::size_t>(n), -1e300);
  s.sx.assign(static_cast<std::size_t>(n), 0.0);
  s.sy.assign(static_cast<std::size_t>(n), 0.0);
  s.mom.assign(static_cast<std::size_t>(n), Eigen::Matrix<double, 5, 1>::Zero());
  const int self_root = self >= 0 ? s.disk.find(self) : -1;
  std::uint64_t sectors = 0;  // 64 bearing sectors holding annulus points
  const double r_mid2 = 0.25 * (cfg.inner_radius_m + R) * (cfg.inner_radius_m + R);
  for (int i = 0; i < n; ++i) {
    if (!s.in_ann[static_cast<std::size_t>(i)]) continue;
    // Sectors from the outer half of the ring only: there a street's two ends are narrow.
    if (coverage_deg && s.rel[static_cast<std::size_t>(i)].head<2>().squaredNorm() >= r_mid2) {
      // Diamond angle in [0, 4) (monotonic in the bearing, within ~4 degrees of linear): no
      // atan2 per point.
      const double dx = s.rel[static_cast<std::size_t>(i)].x();
      const double dy = s.rel[static_cast<std::size_t>(i)].y();
      const double p = dy / std::max(std::abs(dx) + std::abs(dy), 1e-12);
      const double da = dx >= 0 ? (dy >= 0 ? p : 4.0 + p) : 2.0 - p;
      const int sec = std::clamp(static_cast<int>(da * 16.0), 0, 63);
      sectors |= std::uint64_t{1} << sec;
    }
    const auto r = static_cast<std::size_t>(s.ann.find(i));
    ++s.cnt[r];
    const Point3& d = s.rel[static_cast<std::size_t>(i)];
    const double rad = d.head<2>().norm();
    s.rmin[r] = std::min(s.rmin[r], rad);
    s.rmax[r] = std::max(s.rmax[r], rad);
    // Bearing from the outer half of the ring: a parallel carriageway looks close to
    // perpendicular near the inner radius, but runs in the street's direction further out.
    const double wgt = rad >= 0.5 * (cfg.inner_radius_m + cfg.outer_radius_m) ? 1.0 : 1e-3;
    s.sx[r] += wgt * d.x() / rad;
    s.sy[r] += wgt * d.y() / rad;
    s.mom[r] +=
        Eigen::Matrix<double, 5, 1>(d.x(), d.y(), d.x() * d.x(), d.x() * d.y(), d.y() * d.y());
    // No trace point at the centre (a refined node position): connectivity cannot be tested.
    if (self_root < 0 || s.disk.find(i) == self_root) s.conn[r] = 1;
  }
  // Qualified clusters, then one branch per group of clusters that leave the point the same way.
  struct Qual {
    double bearing;     // mean bearing from the point [rad]
    int root;           // annulus cluster
    Eigen::Vector2d c;  // centroid (relative to the point)
    Eigen::Vector2d u;  // principal direction
  };
  std::vector<Qual> quals;
  for (int i = 0; i < n; ++i) {
    const auto r = static_cast<std::size_t>(i);
    if (!s.in_ann[r] || s.ann.find(i) != i) continue;
    if (s.cnt[r] < cfg.min_cluster_points || !s.conn[r] ||
        s.rmax[r] - s.rmin[r] < cfg.min_branch_span_m)
      continue;
    const auto& m = s.mom[r];
    const double k = static_cast<double>(s.cnt[r]);
    const Eigen::Vector2d c(m[0] / k, m[1] / k);
    const double cxx = m[2] / k - c.x() * c.x(), cxy = m[3] / k - c.x() * c.y(),
                 cyy = m[4] / k - c.y() * c.y();
    const double th = 0.5 * std::atan2(2.0 * cxy, cxx - cyy);  // principal axis angle
    quals.push_back({std::atan2(s.sy[r], s.sx[r]), i, c, {std::cos(th), std::sin(th)}});
  }
  std::sort(quals.begin(), quals.end(),
            [](const Qual& a, const Qual& b) { return a.bearing < b.bearing; });
  const std::size_t nq = quals.size();
  UnionFind& grp = s.grp;
  grp.reset(nq);
  // (a) Clusters closer in bearing than min_branch_angle_deg (neighbours in bearing order).
  const double min_gap = cfg.min_branch_angle_deg * M_PI / 180.0;
  for (std::size_t q = 1; q < nq; ++q)
    if (quals[q].bearing - quals[q - 1].bearing < min_gap)
      grp.unite(static_cast<int>(q), static_cast<int>(q - 1));
  if (nq > 1 && quals.front().bearing + 2 * M_PI - quals.back().bearing < min_gap)
    grp.unite(0, static_cast<int>(nq - 1));
  // (b) The other carriageway of a divided road: a parallel cluster (axes within
  //     parallel_angle_deg) on the same side of the point (bearings < 90 degrees apart) whose
  //     centre line is less than carriageway_gap_m away. Seen from a bend of a wide divided road
  //     the two carriageways can be > min_branch_angle_deg apart in bearing.
  const double cos_par = std::cos(cfg.parallel_angle_deg * M_PI / 180.0);
  for (std::size_t a = 0; a < nq; ++a)
    for (std::size_t b = a + 1; b < nq; ++b) {
      const Qual &qa = quals[a], &qb = quals[b];
      if (std::cos(qb.bearing - qa.bearing) <= 0.0) continue;
      if (std::abs(qa.u.dot(qb.u)) < cos_par) continue;
      const Eigen::Vector2d d = qb.c - qa.c;
      const double off_a = std::abs(d.x() * qa.u.y() - d.y() * qa.u.x());
      const double off_b = std::abs(d.x() * qb.u.y() - d.y() * qb.u.x());
      if (std::max(off_a, off_b) < cfg.carriageway_gap_m)
        grp.unite(static_cast<int>(a), static_cast<int>(b));
    }
  std::vector<int>& group = s.group;
  group.assign(nq, -1);
  int branches = 0;
  for (std::size_t q = 0; q < nq; ++q) {
    const auto r = static_cast<std::size_t>(grp.find(static_cast<int>(q)));
    if (group[r] < 0) group[r] = branches++;
    group[q] = group[r];
  }
  if (members) {
    members->assign(static_cast<std::size_t>(branches), {});
    std::vector<int> branch_of(static_cast<std::size_t>(n), -1);
    for (std::size_t q = 0; q < nq; ++q)
      branch_of[static_cast<std::size_t>(quals[q].root)] = group[q];
    for (int i = 0; i < n; ++i) {
      if (!s.in_ann[static_cast<std::size_t>(i)]) continue;
      const int b = branch_of[static_cast<std::size_t>(s.ann.find(i))];
      if (b >= 0)
        (*members)[static_cast<std::size_t>(b)].push_back(s.local[static_cast<std::size_t>(i)]);
    }
  }
  if (coverage_deg) *coverage_deg = 360.0 / 64.0 * static_cast<double>(std::popcount(sectors));
  return branches;
}

}  // namespace slamroute::roadgraph::detail
