// Paper §3.1 step 1: a trace point is an intersection point when the trace points inside a hollow
// cylinder around it (inner 10 m, outer 25 m, height 10 m) form >= 3 Euclidean clusters; the
// intersection points of one junction are merged into one node.
//
// Choices the paper leaves open (documented here, configurable in NodeConfig):
// - Trace points are first thinned to one centroid per 1 m voxel: several vehicles driving the
//   same street at 10 Hz give many near-duplicate points; the test only needs the shape.
// - Clusters smaller than min_cluster_points, or spanning less than min_branch_span_m radially,
//   are GPS noise or the two lane stubs of a dead end, not roads leaving the point.
// - Clusters whose mean bearings from the point differ by less than min_branch_angle_deg are one
//   branch: the two carriageways of a divided road (or a lane splitting off) leave the point in
//   the same direction, while the arms of a junction are >= 45 degrees apart in practice.
// - require_connected: only clusters linked to the point itself through trace points inside the
//   outer disk count as branches. A parallel street 20 m away crosses the cylinder too, but it is
//   not a way out of this point; without the check every point of a street with a close parallel
//   neighbour (or a divided road's other carriageway) would look like an intersection.
// - The node position is the least-squares crossing of the branch centre lines (each branch's
//   principal axis), started from the coordinate-wise median of the intersection points. The
//   median alone is pulled towards the stem of a T junction; the line crossing is not.
#include "slamroute/roadgraph/Intersections.hpp"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <unordered_map>

#include "PointGrid.hpp"
#include "slamroute/core/Log.hpp"

namespace slamroute::roadgraph {
namespace detail {

std::vector<int> euclideanComponents(const std::vector<Point3>& pts, double tol, int* count) {
  PointGrid grid(pts, std::max(tol, 0.1));
  UnionFind uf(pts.size());
  const double tol2 = tol * tol;
  for (int i = 0; i < static_cast<int>(pts.size()); ++i) {
    const Point3& p = pts[static_cast<std::size_t>(i)];
    grid.forEachNear(p, tol, tol, [&](int j) {
      if (j > i && (pts[static_cast<std::size_t>(j)] - p).squaredNorm() <= tol2) uf.unite(i, j);
    });
  }
  std::vector<int> label(pts.size(), -1);
  std::unordered_map<int, int> ids;
  for (int i = 0; i < static_cast<int>(pts.size()); ++i) {
    const int r = uf.find(i);
    auto it = ids.find(r);
    if (it == ids.end()) it = ids.emplace(r, static_cast<int>(ids.size())).first;
    label[static_cast<std::size_t>(i)] = it->second;
  }
  if (count) *count = static_cast<int>(ids.size());
  return label;
}

}  // namespace detail

namespace {

using detail::PointGrid;
using detail::UnionFind;

/// Reusable buffers of one hollow-cylinder test (one per thread).
struct Scratch {
  std::vector<int> local;
  std::vector<Point3> rel;
  std::vector<char> in_ann;
  std::vector<int> heads, next, cnt;
  std::vector<double> rmin, rmax, sx, sy;
  std::vector<char> conn;
  UnionFind disk, ann;
};

/// Hollow-cylinder test around c: the branches (annulus clusters) as lists of point indices when
/// `members` is given; returns their number.
int branchesAt(const PointGrid& grid, const std::vector<Point3>& pts, const Point3& c,
               const NodeConfig& cfg, Scratch& s, std::vector<std::vector<int>>* members) {
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
  if (n == 0) return 0;
  const int G = static_cast<int>(std::ceil(2.0 * R / tol)) + 1;
  s.heads.assign(static_cast<std::size_t>(G) * static_cast<std::size_t>(G), -1);
  s.next.assign(static_cast<std::size_t>(n), -1);
  auto cellOf = [&](double v) { return std::clamp(static_cast<int>((v + R) / tol), 0, G - 1); };
  for (int i = 0; i < n; ++i) {
    const auto& d = s.rel[static_cast<std::size_t>(i)];
    const std::size_t h = static_cast<std::size_t>(cellOf(d.x())) * static_cast<std::size_t>(G) +
                          static_cast<std::size_t>(cellOf(d.y()));
    s.next[static_cast<std::size_t>(i)] = s.heads[h];
    s.heads[h] = i;
  }
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
    const int gx = cellOf(di.x()), gy = cellOf(di.y());
    for (int ax = std::max(0, gx - 1); ax <= std::min(G - 1, gx + 1); ++ax)
      for (int ay = std::max(0, gy - 1); ay <= std::min(G - 1, gy + 1); ++ay)
        for (int j = s.heads[static_cast<std::size_t>(ax) * static_cast<std::size_t>(G) +
                             static_cast<std::size_t>(ay)];
             j >= 0; j = s.next[static_cast<std::size_t>(j)]) {
          if (j <= i || (s.rel[static_cast<std::size_t>(j)] - di).squaredNorm() > tol2) continue;
          s.disk.unite(i, j);
          if (s.in_ann[static_cast<std::size_t>(i)] && s.in_ann[static_cast<std::size_t>(j)])
            s.ann.unite(i, j);
        }
  }
  s.cnt.assign(static_cast<std::size_t>(n), 0);
  s.conn.assign(static_cast<std::size_t>(n), cfg.require_connected ? 0 : 1);
  s.rmin.assign(static_cast<std::size_t>(n), 1e300);
  s.rmax.assign(static_cast<std::size_t>(n), -1e300);
  s.sx.assign(static_cast<std::size_t>(n), 0.0);
  s.sy.assign(static_cast<std::size_t>(n), 0.0);
  const int self_root = self >= 0 ? s.disk.find(self) : -1;
  for (int i = 0; i < n; ++i) {
    if (!s.in_ann[static_cast<std::size_t>(i)]) continue;
    const auto r = static_cast<std::size_t>(s.ann.find(i));
    ++s.cnt[r];
    const double rad = s.rel[static_cast<std::size_t>(i)].head<2>().norm();
    s.rmin[r] = std::min(s.rmin[r], rad);
    s.rmax[r] = std::max(s.rmax[r], rad);
    // Bearing from the outer half of the ring: a parallel carriageway looks close to
    // perpendicular near the inner radius, but runs in the street's direction further out.
    const double wgt = rad >= 0.5 * (cfg.inner_radius_m + cfg.outer_radius_m) ? 1.0 : 1e-3;
    s.sx[r] += wgt * s.rel[static_cast<std::size_t>(i)].x() / rad;
    s.sy[r] += wgt * s.rel[static_cast<std::size_t>(i)].y() / rad;
    // No trace point at the centre (a refined node position): connectivity cannot be tested.
    if (self_root < 0 || s.disk.find(i) == self_root) s.conn[r] = 1;
  }
  // Qualified clusters, then clusters with close bearings merged into one branch.
  std::vector<std::pair<double, int>> quals;  // (bearing, root)
  for (int i = 0; i < n; ++i) {
    const auto r = static_cast<std::size_t>(i);
    if (!s.in_ann[r] || s.ann.find(i) != i) continue;
    if (s.cnt[r] >= cfg.min_cluster_points && s.conn[r] &&
        s.rmax[r] - s.rmin[r] >= cfg.min_branch_span_m)
      quals.emplace_back(std::atan2(s.sy[r], s.sx[r]), i);
  }
  std::sort(quals.begin(), quals.end());
  const double min_gap = cfg.min_branch_angle_deg * M_PI / 180.0;
  std::vector<int> group(quals.size(), 0);
  int branches = quals.empty() ? 0 : 1;
  for (std::size_t q = 1; q < quals.size(); ++q) {
    if (quals[q].first - quals[q - 1].first >= min_gap) ++branches;
    group[q] = branches - 1;
  }
  if (quals.size() > 1 && branches > 1 &&
      quals.front().first + 2 * M_PI - quals.back().first < min_gap) {
    for (auto& gq : group)
      if (gq == branches - 1) gq = 0;  // wrap-around: last group joins the first
    --branches;
  }
  std::vector<int> branch_of;
  if (members) {
    members->assign(static_cast<std::size_t>(branches), {});
    branch_of.assign(static_cast<std::size_t>(n), -1);
    for (std::size_t q = 0; q < quals.size(); ++q)
      branch_of[static_cast<std::size_t>(quals[q].second)] = group[q];
  }
  if (members)
    for (int i = 0; i < n; ++i) {
      if (!s.in_ann[static_cast<std::size_t>(i)]) continue;
      const int b = branch_of[static_cast<std::size_t>(s.ann.find(i))];
      if (b >= 0) (*members)[static_cast<std::size_t>(b)].push_back(s.local[static_cast<std::size_t>(i)]);
    }
  return branches;
}

double median(std::vector<double> v) {
  const auto mid = v.begin() + static_cast<long>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

/// Least-squares crossing of the branches' principal lines (horizontal), z unchanged.
Point3 refineCentre(const PointGrid& grid, const std::vector<Point3>& pts, const Point3& start,
                    const NodeConfig& cfg, Scratch& s) {
  Point3 c = start;
  std::vector<std::vector<int>> members;
  for (int iter = 0; iter < 3; ++iter) {
    if (branchesAt(grid, pts, c, cfg, s, &members) < 2) break;
    Eigen::Matrix2d A = Eigen::Matrix2d::Zero();
    Eigen::Vector2d b = Eigen::Vector2d::Zero();
    for (const auto& m : members) {
      Eigen::Vector2d mean = Eigen::Vector2d::Zero();
      for (int i : m) mean += pts[static_cast<std::size_t>(i)].head<2>();
      mean /= static_cast<double>(m.size());
      Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
      for (int i : m) {
        const Eigen::Vector2d d = pts[static_cast<std::size_t>(i)].head<2>() - mean;
        cov += d * d.transpose();
      }
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(cov);
      const Eigen::Vector2d dir = es.eigenvectors().col(1);
      const Eigen::Matrix2d P = Eigen::Matrix2d::Identity() - dir * dir.transpose();
      A += P;
      b += P * mean;
    }
    if (A.determinant() < 0.05 * static_cast<double>(members.size())) break;  // near-parallel
    const Eigen::Vector2d x = A.ldlt().solve(b);
    if ((x - start.head<2>()).norm() > cfg.inner_radius_m) break;  // implausible jump
    const bool done = (x - c.head<2>()).norm() < 0.05;
    c.head<2>() = x;
    if (done) break;
  }
  return c;
}

}  // namespace

Downsampled downsample(const std::vector<Point3>& pts, double voxel_m) {
  if (!(voxel_m > 0.0)) throw std::invalid_argument("roadgraph.nodes.downsample_m must be > 0");
  Downsampled out;
  out.voxel_of.resize(pts.size());
  std::unordered_map<std::uint64_t, int> index;
  index.reserve(pts.size() / 2 + 16);
  std::vector<int> count;
  auto q = [&](double v) {
    return static_cast<std::uint64_t>(static_cast<std::int64_t>(std::floor(v / voxel_m))) &
           0x1FFFFFu;
  };
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const std::uint64_t key = (q(pts[i].x()) << 42) | (q(pts[i].y()) << 21) | q(pts[i].z());
    auto [it, inserted] = index.emplace(key, static_cast<int>(out.points.size()));
    if (inserted) {
      out.points.push_back(Point3::Zero());
      count.push_back(0);
    }
    out.points[static_cast<std::size_t>(it->second)] += pts[i];
    ++count[static_cast<std::size_t>(it->second)];
    out.voxel_of[i] = it->second;
  }
  for (std::size_t v = 0; v < out.points.size(); ++v) out.points[v] /= count[v];
  return out;
}

int countBranches(const std::vector<Point3>& pts, const Point3& centre, const NodeConfig& cfg) {
  PointGrid grid(pts, 5.0);
  Scratch s;
  return branchesAt(grid, pts, centre, cfg, s, nullptr);
}

IntersectionResult detectIntersections(const std::vector<Point3>& pts, const NodeConfig& cfg) {
  if (!(cfg.inner_radius_m >= 0.0 && cfg.outer_radius_m > cfg.inner_radius_m &&
        cfg.height_m > 0.0 && cfg.cluster_tolerance_m > 0.0))
    throw std::invalid_argument(
        "roadgraph.nodes: need 0 <= inner_radius_m < outer_radius_m, height_m > 0, "
        "cluster_tolerance_m > 0");
  IntersectionResult res;
  const std::size_t n = pts.size();
  res.is_intersection.assign(n, 0);
  res.node_of_point.assign(n, -1);
  const PointGrid grid(pts, 5.0);

  // 1. Hollow-cylinder test of every point (independent -> parallel, deterministic).
  std::vector<int> nbranch(n, 0);
  tbb::enumerable_thread_specific<Scratch> scratch;
  Progress progress("intersections", n);
  const std::size_t chunk = 20000;
  for (std::size_t b = 0; b < n; b += chunk) {
    const std::size_t e = std::min(n, b + chunk);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(b, e, 256), [&](const auto& r) {
      Scratch& s = scratch.local();
      for (std::size_t i = r.begin(); i != r.end(); ++i)
        nbranch[i] = branchesAt(grid, pts, pts[i], cfg, s, nullptr);
    });
    progress.update(e);
  }
  progress.finish();

  for (std::size_t i = 0; i < n; ++i) res.is_intersection[i] = nbranch[i] >= cfg.min_branches;

  // 2. Group the intersection points into junctions: greedy seeds, most branches first, then the
  //    densest (arms of a junction overlap at its centre); a seed takes the free intersection
  //    points within node_radius_m. Unlike plain connected components this also splits a chain
  //    of junctions closer together than the cylinder into several nodes.
  std::vector<int> ipts;
  std::vector<Point3> ipos;
  for (std::size_t i = 0; i < n; ++i)
    if (res.is_intersection[i]) {
      ipts.push_back(static_cast<int>(i));
      ipos.push_back(pts[i]);
    }
  const PointGrid igrid(ipos, std::max(cfg.node_radius_m, 1.0));
  std::vector<int> density(ipos.size(), 0);
  for (std::size_t k = 0; k < ipos.size(); ++k)
    igrid.forEachNear(ipos[k], cfg.merge_distance_m, 0.5 * cfg.height_m,
                      [&](int) { ++density[k]; });
  std::vector<int> order(ipos.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = static_cast<int>(k);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    const int ba = nbranch[static_cast<std::size_t>(ipts[static_cast<std::size_t>(a)])];
    const int bb = nbranch[static_cast<std::size_t>(ipts[static_cast<std::size_t>(b)])];
    if (ba != bb) return ba > bb;
    if (density[static_cast<std::size_t>(a)] != density[static_cast<std::size_t>(b)])
      return density[static_cast<std::size_t>(a)] > density[static_cast<std::size_t>(b)];
    return a < b;
  });
  std::vector<char> taken(ipos.size(), 0);
  std::vector<std::vector<int>> comps;
  for (int seed : order) {
    if (taken[static_cast<std::size_t>(seed)]) continue;
    comps.emplace_back();
    igrid.forEachNear(ipos[static_cast<std::size_t>(seed)], cfg.node_radius_m, 0.5 * cfg.height_m,
                      [&](int k) {
                        if (taken[static_cast<std::size_t>(k)]) return;
                        taken[static_cast<std::size_t>(k)] = 1;
                        comps.back().push_back(k);
                      });
    std::sort(comps.back().begin(), comps.back().end());
  }

  // 3. One node per group: median start, least-squares crossing of the arms.
  Scratch s;
  std::vector<Point3> centres;
  std::vector<std::vector<int>> owned;
  for (const auto& comp : comps) {
    if (static_cast<int>(comp.size()) < cfg.min_node_points) continue;
    std::vector<double> xs, ys, zs;
    for (int k : comp) {
      xs.push_back(ipos[static_cast<std::size_t>(k)].x());
      ys.push_back(ipos[static_cast<std::size_t>(k)].y());
      zs.push_back(ipos[static_cast<std::size_t>(k)].z());
    }
    Point3 c(median(xs), median(ys), median(zs));
    // The node must pass the test itself: a fragment of intersection points on an arm (noise)
    // sees only the two ways of its street from its median.
    const int b0 = branchesAt(grid, pts, c, cfg, s, nullptr);
    if (b0 < cfg.min_branches) continue;
    logDebug("node: median (" + std::to_string(c.x()) + ", " + std::to_string(c.y()) + ") from " +
             std::to_string(comp.size()) + " intersection points, " + std::to_string(b0) +
             " branches");
    if (cfg.refine_centre) {
      // Keep the refined centre only when it still sees the junction's branches (curved arms
      // or wide junctions can mislead the line fit).
      const Point3 cr = refineCentre(grid, pts, c, cfg, s);
      if (branchesAt(grid, pts, cr, cfg, s, nullptr) >= b0) c = cr;
    }
    centres.push_back(c);
    owned.push_back(comp);
  }
  // 4. Nodes whose centres ended up closer than merge_distance_m are one junction.
  int nn = 0;
  const auto nlabel = detail::euclideanComponents(centres, cfg.merge_distance_m, &nn);
  std::vector<Point3> sum(static_cast<std::size_t>(nn), Point3::Zero());
  std::vector<int> cnt(static_cast<std::size_t>(nn), 0);
  for (std::size_t k = 0; k < centres.size(); ++k) {
    sum[static_cast<std::size_t>(nlabel[k])] += centres[k];
    ++cnt[static_cast<std::size_t>(nlabel[k])];
    for (int q : owned[k])
      res.node_of_point[static_cast<std::size_t>(ipts[static_cast<std::size_t>(q)])] = nlabel[k];
  }
  for (int k = 0; k < nn; ++k) {
    res.nodes.push_back(sum[static_cast<std::size_t>(k)] / cnt[static_cast<std::size_t>(k)]);
    res.branches.push_back(branchesAt(grid, pts, res.nodes.back(), cfg, s, nullptr));
  }
  return res;
}

}  // namespace slamroute::roadgraph
