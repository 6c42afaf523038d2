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
namespace {

/// The points within the outer radius around c (inner ones only when connectivity is tested);
/// returns their number.
int gatherCylinder(const PointGrid& grid, const std::vector<Point3>& pts, const Point3& c,
                   const NodeConfig& cfg, Scratch& s) {
  const double r_in2 = cfg.inner_radius_m * cfg.inner_radius_m;
  s.local.clear();
  s.rel.clear();
  s.in_annulus.clear();
  grid.forEachNear(c, cfg.outer_radius_m, 0.5 * cfg.height_m, [&](int i) {
    const Point3 d = pts[static_cast<std::size_t>(i)] - c;
    const bool in_annulus = d.x() * d.x() + d.y() * d.y() >= r_in2;
    if (!in_annulus && !cfg.require_connected) return;  // inner points only matter for linking
    s.local.push_back(i);
    s.rel.push_back(d);
    s.in_annulus.push_back(in_annulus ? 1 : 0);
  });
  return static_cast<int>(s.local.size());
}

/// Euclidean clusters of the n gathered points: s.disk_sets over all of them, s.annulus_sets
/// over the annulus points only (unite keeps the smallest index as root, so the order of the
/// pairs does not matter). Returns the gathered point nearest the centre within the clustering
/// distance, -1 when there is none.
int clusterCylinder(const PointGrid& grid, std::size_t n_all, const NodeConfig& cfg, Scratch& s,
                    int n) {
  const double tol = cfg.cluster_tolerance_m;
  if (grid.linkTolerance() != tol)
    throw std::logic_error("branchesAt: the point grid is not linked at cluster_tolerance_m");
  if (s.local_of.size() != n_all) s.local_of.assign(n_all, -1);
  for (int i = 0; i < n; ++i)
    s.local_of[static_cast<std::size_t>(s.local[static_cast<std::size_t>(i)])] = i;
  s.disk_sets.reset(static_cast<std::size_t>(n));
  s.annulus_sets.reset(static_cast<std::size_t>(n));
  int self = -1;
  double self_d2 = tol * tol;
  for (int i = 0; i < n; ++i) {
    const auto& di = s.rel[static_cast<std::size_t>(i)];
    if (di.squaredNorm() <= self_d2) {
      self_d2 = di.squaredNorm();
      self = i;
    }
    grid.forEachLinked(s.local[static_cast<std::size_t>(i)], [&](int g) {
      const int j = s.local_of[static_cast<std::size_t>(g)];
      if (j <= i) return;
      s.disk_sets.unite(i, j);
      if (s.in_annulus[static_cast<std::size_t>(i)] && s.in_annulus[static_cast<std::size_t>(j)])
        s.annulus_sets.unite(i, j);
    });
  }
  for (int i : s.local) s.local_of[static_cast<std::size_t>(i)] = -1;
  return self;
}

/// Bearing sector (of 64) of an offset: the diamond angle in [0, 4) is monotonic in the bearing
/// and within ~4 degrees of linear, so no atan2 per point.
int bearingSector(double dx, double dy) {
  const double p = dy / std::max(std::abs(dx) + std::abs(dy), 1e-12);
  const double da = dx >= 0 ? (dy >= 0 ? p : 4.0 + p) : 2.0 - p;
  return std::clamp(static_cast<int>(da * 16.0), 0, 63);
}

void resetClusterSums(const NodeConfig& cfg, Scratch& s, int n) {
  const auto m = static_cast<std::size_t>(n);
  s.cluster_points.assign(m, 0);
  s.reaches_centre.assign(m, cfg.require_connected ? 0 : 1);
  s.radius_min.assign(m, 1e300);
  s.radius_max.assign(m, -1e300);
  s.bearing_x.assign(m, 0.0);
  s.bearing_y.assign(m, 0.0);
  s.moments.assign(m, Eigen::Matrix<double, 5, 1>::Zero());
}

/// Sums per annulus cluster (size, radial extent, bearing, moments, link to the centre point
/// `self`); returns the 64 bearing sectors the outer half of the ring holds points in, where a
/// street's two ends are narrow.
std::uint64_t sumClusters(const NodeConfig& cfg, Scratch& s, int n, int self) {
  resetClusterSums(cfg, s, n);
  const int self_root = self >= 0 ? s.disk_sets.find(self) : -1;
  std::uint64_t sectors = 0;
  const double r_mid = 0.5 * (cfg.inner_radius_m + cfg.outer_radius_m);
  for (int i = 0; i < n; ++i) {
    if (!s.in_annulus[static_cast<std::size_t>(i)]) continue;
    const Point3& d = s.rel[static_cast<std::size_t>(i)];
    const double rad = d.head<2>().norm();
    if (d.head<2>().squaredNorm() >= r_mid * r_mid)
      sectors |= std::uint64_t{1} << bearingSector(d.x(), d.y());
    const auto r = static_cast<std::size_t>(s.annulus_sets.find(i));
    ++s.cluster_points[r];
    s.radius_min[r] = std::min(s.radius_min[r], rad);
    s.radius_max[r] = std::max(s.radius_max[r], rad);
    // Bearing from the outer half of the ring: a parallel carriageway looks close to
    // perpendicular near the inner radius, but runs in the street's direction further out.
    const double wgt = rad >= r_mid ? 1.0 : 1e-3;
    s.bearing_x[r] += wgt * d.x() / rad;
    s.bearing_y[r] += wgt * d.y() / rad;
    s.moments[r] +=
        Eigen::Matrix<double, 5, 1>(d.x(), d.y(), d.x() * d.x(), d.x() * d.y(), d.y() * d.y());
    // No trace point at the centre (a refined node position): connectivity cannot be tested.
    if (self_root < 0 || s.disk_sets.find(i) == self_root) s.reaches_centre[r] = 1;
  }
  return sectors;
}

/// An annulus cluster that qualifies as (part of) a branch.
struct Qualified {
  double bearing;            // mean bearing from the point [rad]
  int root;                  // annulus cluster
  Eigen::Vector2d centroid;  // relative to the point
  Eigen::Vector2d axis;      // principal direction
};

/// Clusters big enough, long enough radially and linked to the point, by bearing.
std::vector<Qualified> qualifiedClusters(const NodeConfig& cfg, Scratch& s, int n) {
  std::vector<Qualified> quals;
  for (int i = 0; i < n; ++i) {
    const auto r = static_cast<std::size_t>(i);
    if (!s.in_annulus[r] || s.annulus_sets.find(i) != i) continue;
    if (s.cluster_points[r] < cfg.min_cluster_points || !s.reaches_centre[r] ||
        s.radius_max[r] - s.radius_min[r] < cfg.min_branch_span_m)
      continue;
    const auto& m = s.moments[r];
    const double k = static_cast<double>(s.cluster_points[r]);
    const Eigen::Vector2d c(m[0] / k, m[1] / k);
    const double cxx = m[2] / k - c.x() * c.x(), cxy = m[3] / k - c.x() * c.y(),
                 cyy = m[4] / k - c.y() * c.y();
    const double th = 0.5 * std::atan2(2.0 * cxy, cxx - cyy);  // principal axis angle
    quals.push_back(
        {std::atan2(s.bearing_y[r], s.bearing_x[r]), i, c, {std::cos(th), std::sin(th)}});
  }
  std::sort(quals.begin(), quals.end(),
            [](const Qualified& a, const Qualified& b) { return a.bearing < b.bearing; });
  return quals;
}

/// The other carriageway of a divided road: a parallel cluster (axes within parallel_angle_deg)
/// on the same side of the point (bearings < 90 degrees apart) whose centre line is less than
/// carriageway_gap_m away. Seen from a bend of a wide divided road the two carriageways can be
/// more than min_branch_angle_deg apart in bearing.
bool otherCarriageway(const Qualified& a, const Qualified& b, const NodeConfig& cfg) {
  if (std::cos(b.bearing - a.bearing) <= 0.0) return false;
  if (std::abs(a.axis.dot(b.axis)) < std::cos(cfg.parallel_angle_deg * M_PI / 180.0)) return false;
  const Eigen::Vector2d d = b.centroid - a.centroid;
  const double off_a = std::abs(d.x() * a.axis.y() - d.y() * a.axis.x());
  const double off_b = std::abs(d.x() * b.axis.y() - d.y() * b.axis.x());
  return std::max(off_a, off_b) < cfg.carriageway_gap_m;
}

/// One branch per group of qualified clusters that leave the point the same way: neighbours in
/// bearing closer than min_branch_angle_deg, or the two carriageways of a divided road. Fills
/// s.branch_of_cluster (per qualified cluster) and returns the number of branches.
int groupIntoBranches(const std::vector<Qualified>& quals, const NodeConfig& cfg, Scratch& s) {
  const std::size_t nq = quals.size();
  UnionFind& sets = s.branch_sets;
  sets.reset(nq);
  const double min_gap = cfg.min_branch_angle_deg * M_PI / 180.0;
  for (std::size_t q = 1; q < nq; ++q)
    if (quals[q].bearing - quals[q - 1].bearing < min_gap)
      sets.unite(static_cast<int>(q), static_cast<int>(q - 1));
  if (nq > 1 && quals.front().bearing + 2 * M_PI - quals.back().bearing < min_gap)
    sets.unite(0, static_cast<int>(nq - 1));
  for (std::size_t a = 0; a < nq; ++a)
    for (std::size_t b = a + 1; b < nq; ++b)
      if (otherCarriageway(quals[a], quals[b], cfg))
        sets.unite(static_cast<int>(a), static_cast<int>(b));
  std::vector<int>& branch = s.branch_of_cluster;
  branch.assign(nq, -1);
  int branches = 0;
  for (std::size_t q = 0; q < nq; ++q) {
    const auto r = static_cast<std::size_t>(sets.find(static_cast<int>(q)));
    if (branch[r] < 0) branch[r] = branches++;
    branch[q] = branch[r];
  }
  return branches;
}

/// The points (indices into the whole set) of each branch.
void branchMembers(const std::vector<Qualified>& quals, int branches, Scratch& s, int n,
                   std::vector<std::vector<int>>& members) {
  members.assign(static_cast<std::size_t>(branches), {});
  std::vector<int> branch_of_root(static_cast<std::size_t>(n), -1);
  for (std::size_t q = 0; q < quals.size(); ++q)
    branch_of_root[static_cast<std::size_t>(quals[q].root)] = s.branch_of_cluster[q];
  for (int i = 0; i < n; ++i) {
    if (!s.in_annulus[static_cast<std::size_t>(i)]) continue;
    const int b = branch_of_root[static_cast<std::size_t>(s.annulus_sets.find(i))];
    if (b >= 0)
      members[static_cast<std::size_t>(b)].push_back(s.local[static_cast<std::size_t>(i)]);
  }
}

}  // namespace

int branchesAt(const PointGrid& grid, const std::vector<Point3>& pts, const Point3& c,
               const NodeConfig& cfg, Scratch& s, std::vector<std::vector<int>>* members,
               double* coverage_deg) {
  if (coverage_deg) *coverage_deg = 0.0;
  const int n = gatherCylinder(grid, pts, c, cfg, s);
  if (n == 0) return 0;
  const int self = clusterCylinder(grid, pts.size(), cfg, s, n);
  const std::uint64_t sectors = sumClusters(cfg, s, n, self);
  const std::vector<Qualified> quals = qualifiedClusters(cfg, s, n);
  const int branches = groupIntoBranches(quals, cfg, s);
  if (members) branchMembers(quals, branches, s, n, *members);
  if (coverage_deg) *coverage_deg = 360.0 / 64.0 * static_cast<double>(std::popcount(sectors));
  return branches;
}

}  // namespace slamroute::roadgraph::detail
