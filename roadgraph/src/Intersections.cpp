// Paper §3.1 step 1: a trace point is an intersection point when the trace points inside a hollow
// cylinder around it (inner 10 m, outer 25 m, height 10 m) form >= 3 Euclidean clusters; the
// intersection points of one junction are merged into one node (position = robust centre).
//
// Choices the paper leaves open (documented here, configurable in NodeConfig):
// - Trace points are first thinned to one centroid per 2 m voxel: several vehicles driving the
//   same street at 10 Hz give many near-duplicate points; the test only needs the shape, and the
//   4 m clustering distance keeps 2 m voxels of one road linked.
// - Clusters smaller than min_cluster_points, or spanning less than min_branch_span_m radially,
//   are GPS noise or the two lane stubs of a dead end, not roads leaving the point.
// - Clusters whose mean bearings from the point differ by less than min_branch_angle_deg are one
//   branch (a lane splitting off), and so are parallel clusters on the same side less than
//   carriageway_gap_m apart (the two carriageways of a divided road, which at a bend can be more
//   than min_branch_angle_deg apart in bearing). Arms of a junction are >= 45 degrees apart.
// - require_connected: only clusters linked to the point itself through trace points inside the
//   outer disk count as branches. A parallel street 20 m away crosses the cylinder too, but it is
//   not a way out of this point; without the check every point of a street with a close parallel
//   neighbour (or a divided road's other carriageway) would look like an intersection.
// - A second ring, radii x wide_scale, is tried where the paper's ring sees < 3 branches but holds
//   points over a wide range of bearings: at big junctions (4-lane avenues, junction boxes of
//   20-40 m) turning traffic runs through the 10-25 m ring and links the arms into one cluster.
// - Robust centre by voting: every intersection point votes for the least-squares crossing of the
//   centre lines of the branches it sees (re-evaluated once at the crossing). Points anywhere in a
//   junction's intersection region (up to ~inner radius + road width from the centre) vote for
//   the same spot, so a wide junction is not split into several nodes. A branch's line is its
//   vehicles' mean travel axis (doubled-angle mean of the trace directions) through the centroid
//   of its points between two cuts perpendicular to it: a wide arm is as wide as it is long
//   inside the ring, so its principal axis tilts by tens of degrees when seen off-centre, and
//   that tilt moves the crossing by metres. Opposite branches on one line are fitted together.
// - Votes are grouped greedily (densest first, node_radius_m); a group's node is the median of its
//   votes and must itself see >= 3 branches in either ring (both are always tried there), unless
//   it holds strong_vote_factor x the median group's votes: at big junctions (SUMO clusters,
//   4-lane arms) turning traffic links the arms in both rings around the centre while the
//   points voting for it, off-centre, see them apart (without the exception Ingolstadt loses 7
//   true junctions with 47-139 votes each). Groups with fewer than min_vote_fraction of the median
//   group's votes are dropped (a bend, a lane split, a noisy stretch collect a handful of votes,
//   a junction tens to hundreds), and a group within merge_distance_m (18 m) of a stronger one
//   is absorbed by it: the carriageway crossings of two divided roads and the corners of a big
//   junction box collect votes of their own 10-16 m apart, and the ring cannot resolve separate
//   junctions that close anyway (they are lost; see bench/RESULTS.md).
#include "slamroute/roadgraph/Intersections.hpp"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <unordered_map>

#include "HollowCylinder.hpp"
#include "Median.hpp"
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

using detail::branchesAt;
using detail::crossingFrom;
using detail::median;
using detail::PointGrid;
using detail::Scratch;
using detail::UnionFind;

}  // namespace

int countBranches(const std::vector<Point3>& pts, const Point3& centre, const NodeConfig& cfg) {
  PointGrid grid(pts, 5.0);
  grid.linkWithin(cfg.cluster_tolerance_m);
  Scratch s;
  return branchesAt(grid, pts, centre, cfg, s, nullptr);
}

namespace {
IntersectionResult detectSorted(const std::vector<Point3>& pts, const NodeConfig& cfg,
                                const std::vector<Eigen::Vector2d>* axes);
}  // namespace

IntersectionResult detectIntersections(const std::vector<Point3>& pts, const NodeConfig& cfg,
                                       const std::vector<Eigen::Vector2d>* axes) {
  if (axes && axes->size() != pts.size()) axes = nullptr;
  // Work on the points in spatial order (Morton order of 32 m tiles): trace order jumps around
  // the city, and with 10^6 points the neighbour look-ups of each test would miss the cache.
  const std::size_t n = pts.size();
  std::vector<std::pair<std::uint64_t, std::uint32_t>> key(n);
  auto spread = [](std::uint64_t v) {  // interleave the low 32 bits with zeros
    v &= 0xFFFFFFFFu;
    v = (v | (v << 16)) & 0x0000FFFF0000FFFFull;
    v = (v | (v << 8)) & 0x00FF00FF00FF00FFull;
    v = (v | (v << 4)) & 0x0F0F0F0F0F0F0F0Full;
    v = (v | (v << 2)) & 0x3333333333333333ull;
    return (v | (v << 1)) & 0x5555555555555555ull;
  };
  for (std::size_t i = 0; i < n; ++i) {
    auto tile = [](double v) {
      return static_cast<std::uint64_t>(static_cast<std::int64_t>(std::floor(v / 32.0)) + (1 << 30));
    };
    const std::uint64_t tx = tile(pts[i].x()), ty = tile(pts[i].y());
    key[i] = {spread(tx) | (spread(ty) << 1), static_cast<std::uint32_t>(i)};
  }
  std::sort(key.begin(), key.end());
  std::vector<Point3> sp(n);
  std::vector<Eigen::Vector2d> sa(axes ? n : 0);
  for (std::size_t k = 0; k < n; ++k) {
    sp[k] = pts[key[k].second];
    if (axes) sa[k] = (*axes)[key[k].second];
  }
  IntersectionResult sorted = detectSorted(sp, cfg, axes ? &sa : nullptr);
  IntersectionResult res;
  res.nodes = std::move(sorted.nodes);
  res.branches = std::move(sorted.branches);
  res.is_intersection.assign(n, 0);
  res.node_of_point.assign(n, -1);
  for (std::size_t k = 0; k < n; ++k) {
    res.is_intersection[key[k].second] = sorted.is_intersection[k];
    res.node_of_point[key[k].second] = sorted.node_of_point[k];
  }
  return res;
}

namespace {
IntersectionResult detectSorted(const std::vector<Point3>& pts, const NodeConfig& cfg,
                                const std::vector<Eigen::Vector2d>* axes) {
  if (!(cfg.inner_radius_m >= 0.0 && cfg.outer_radius_m > cfg.inner_radius_m &&
        cfg.height_m > 0.0 && cfg.cluster_tolerance_m > 0.0))
    throw std::invalid_argument(
        "roadgraph.nodes: need 0 <= inner_radius_m < outer_radius_m, height_m > 0, "
        "cluster_tolerance_m > 0");
  IntersectionResult res;
  const std::size_t n = pts.size();
  res.is_intersection.assign(n, 0);
  res.node_of_point.assign(n, -1);
  PointGrid grid(pts, 5.0);
  grid.linkWithin(cfg.cluster_tolerance_m);

  // Second, larger cylinder (radii x wide_scale): at a big junction (4-lane avenues, a junction
  // box of ~25 m) turning traffic runs through the paper's 10-25 m ring and links the arms into
  // one or two clusters; a ring beyond the junction box still separates them. A point is an
  // intersection point when either ring sees >= min_branches; the ring seeing more branches is
  // used for its vote. Votes of points on an arm near a junction fall on the junction's centre,
  // so the larger ring adds evidence for junctions rather than new nodes.
  NodeConfig wide = cfg;
  wide.inner_radius_m *= cfg.wide_scale;
  wide.outer_radius_m *= cfg.wide_scale;
  const bool use_wide = cfg.wide_scale > 1.0;
  // The larger ring is only tried where the paper's ring holds points over a wide range of
  // bearings (a street, straight or curved, covers two narrow sectors; a junction whose arms the
  // ring sees linked covers most of the circle), which keeps its cost small.
  auto branchesBoth = [&](const Point3& c, Scratch& s, bool* is_wide) {
    double coverage = 0.0;
    const int b1 = branchesAt(grid, pts, c, cfg, s, nullptr, &coverage);
    int b2 = 0;
    if (use_wide && b1 < cfg.min_branches && coverage >= cfg.wide_min_coverage_deg)
      b2 = branchesAt(grid, pts, c, wide, s, nullptr);
    if (is_wide) *is_wide = b2 > b1;
    return std::max(b1, b2);
  };
  // At a candidate node both rings are always tried (a handful of tests, not one per point).
  auto branchesNode = [&](const Point3& c, Scratch& s, bool* is_wide) {
    const int b1 = branchesAt(grid, pts, c, cfg, s, nullptr);
    const int b2 =
        use_wide && b1 < cfg.min_branches ? branchesAt(grid, pts, c, wide, s, nullptr) : 0;
    if (is_wide) *is_wide = b2 > b1;
    return std::max(b1, b2);
  };

  // 1. Hollow-cylinder test of every point (independent -> parallel, deterministic).
  std::vector<int> nbranch(n, 0);
  std::vector<char> by_wide(n, 0);
  tbb::enumerable_thread_specific<Scratch> scratch;
  Progress progress("intersections", n);
  const std::size_t chunk = 20000;
  for (std::size_t b = 0; b < n; b += chunk) {
    const std::size_t e = std::min(n, b + chunk);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(b, e, 256), [&](const auto& r) {
      Scratch& s = scratch.local();
      for (std::size_t i = r.begin(); i != r.end(); ++i) {
        bool w = false;
        nbranch[i] = branchesBoth(pts[i], s, &w);
        by_wide[i] = w ? 1 : 0;
      }
    });
    progress.update(e);
  }
  progress.finish();

  for (std::size_t i = 0; i < n; ++i) res.is_intersection[i] = nbranch[i] >= cfg.min_branches;

  // 2. Each intersection point votes for its junction's centre: the least-squares crossing of
  //    the branches it sees (one re-evaluation at the crossing). Points anywhere in a junction's
  //    intersection region (up to ~inner radius + road width from the centre) vote for the same
  //    spot, so a wide junction is not split into several nodes; a point whose branches give no
  //    stable crossing (near-parallel lines) votes for itself.
  std::vector<int> ipts;
  for (std::size_t i = 0; i < n; ++i)
    if (res.is_intersection[i]) ipts.push_back(static_cast<int>(i));
  std::vector<Point3> votes(ipts.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, ipts.size(), 64), [&](const auto& r) {
    Scratch& s = scratch.local();
    for (std::size_t k = r.begin(); k != r.end(); ++k) {
      const Point3& p = pts[static_cast<std::size_t>(ipts[k])];
      const NodeConfig& vc = by_wide[static_cast<std::size_t>(ipts[k])] ? wide : cfg;
      if (!crossingFrom(grid, pts, axes, p, vc, s, cfg.vote_iterations, cfg.vote_max_m, votes[k]))
        votes[k] = p;
    }
  });

  // 3. Group the votes: greedy seeds, densest first (votes within vote_radius_m); a seed takes
  //    the free votes within node_radius_m. Unlike plain connected components this also splits
  //    a chain of junctions closer together than the cylinder into several nodes.
  const PointGrid vgrid(votes, std::max(cfg.node_radius_m, 1.0));
  std::vector<int> density(votes.size(), 0);
  for (std::size_t k = 0; k < votes.size(); ++k)
    vgrid.forEachNear(votes[k], cfg.vote_radius_m, 0.5 * cfg.height_m, [&](int) { ++density[k]; });
  std::vector<int> order(votes.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = static_cast<int>(k);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    if (density[static_cast<std::size_t>(a)] != density[static_cast<std::size_t>(b)])
      return density[static_cast<std::size_t>(a)] > density[static_cast<std::size_t>(b)];
    return a < b;
  });
  std::vector<char> taken(votes.size(), 0);
  std::vector<std::vector<int>> comps;
  for (int seed : order) {
    if (taken[static_cast<std::size_t>(seed)]) continue;
    comps.emplace_back();
    vgrid.forEachNear(votes[static_cast<std::size_t>(seed)], cfg.node_radius_m, 0.5 * cfg.height_m,
                      [&](int k) {
                        if (taken[static_cast<std::size_t>(k)]) return;
                        taken[static_cast<std::size_t>(k)] = 1;
                        comps.back().push_back(k);
                      });
    std::sort(comps.back().begin(), comps.back().end());
  }

  // 4. One node per group: median of its votes (robust centre), optionally (refine_centre) the
  //    crossing of the arms seen from there.
  Scratch s;
  double median_votes = 0.0;
  {
    std::vector<double> sizes;
    for (const auto& comp : comps)
      if (static_cast<int>(comp.size()) >= cfg.min_node_points)
        sizes.push_back(static_cast<double>(comp.size()));
    if (!sizes.empty()) median_votes = median(sizes);
  }
  std::vector<Point3> centres;
  std::vector<std::vector<int>> owned;
  for (const auto& comp : comps) {
    if (static_cast<int>(comp.size()) < cfg.min_node_points) continue;
    std::vector<double> xs, ys, zs;
    for (int k : comp) {
      xs.push_back(votes[static_cast<std::size_t>(k)].x());
      ys.push_back(votes[static_cast<std::size_t>(k)].y());
      zs.push_back(votes[static_cast<std::size_t>(k)].z());
    }
    Point3 c(median(xs), median(ys), median(zs));
    // The node must pass the test itself: a fragment of intersection points on an arm (noise)
    // sees only the two ways of its street from its median. A strongly voted group need not.
    bool w0 = false;
    const int b0 = branchesNode(c, s, &w0);
    if (b0 < cfg.min_branches &&
        !(cfg.strong_vote_factor > 0.0 &&
          static_cast<double>(comp.size()) >= cfg.strong_vote_factor * median_votes))
      continue;
    logDebug("node: vote median (" + std::to_string(c.x()) + ", " + std::to_string(c.y()) +
             ") from " + std::to_string(comp.size()) + " votes, " + std::to_string(b0) +
             " branches");
    if (cfg.refine_centre) {
      // Keep the refined centre only when it still sees the junction's branches (curved arms
      // or wide junctions can mislead the line fit).
      Point3 cr;
      crossingFrom(grid, pts, axes, c, w0 ? wide : cfg, s, 3, cfg.inner_radius_m, cr);
      if (branchesNode(cr, s, nullptr) >= b0) c = cr;
    }
    centres.push_back(c);
    owned.push_back(comp);
  }
  // Weakly supported candidates: fewer votes than min_vote_fraction of the median candidate. A
  // junction driven through by traffic collects votes from its whole intersection region (tens
  // to hundreds of points); a bend of a wide road, a lane split or a noisy stretch collects a
  // handful. Relative to the median so it adapts to the survey's density (voxel size, traffic).
  if (!centres.empty() && cfg.min_vote_fraction > 0.0) {
    std::vector<double> nv;
    for (const auto& o : owned) nv.push_back(static_cast<double>(o.size()));
    const double need = cfg.min_vote_fraction * median(nv);
    std::size_t kept = 0;
    for (std::size_t k = 0; k < centres.size(); ++k)
      if (static_cast<double>(owned[k].size()) >= need) {
        if (kept != k) {  // a self-move would empty the vote list
          centres[kept] = centres[k];
          owned[kept] = std::move(owned[k]);
        }
        ++kept;
      }
    centres.resize(kept);
    owned.resize(kept);
  }
  // 5. Candidates closer than merge_distance_m are one junction (the ring cannot resolve
  //    junctions much closer than its inner radius): strongest (most votes) first, a weaker
  //    candidate near an accepted node is absorbed by it and keeps no position of its own.
  std::vector<std::size_t> byvotes(centres.size());
  for (std::size_t k = 0; k < byvotes.size(); ++k) byvotes[k] = k;
  std::stable_sort(byvotes.begin(), byvotes.end(), [&](std::size_t a, std::size_t b) {
    return owned[a].size() > owned[b].size();
  });
  for (std::size_t k : byvotes) {
    int node = -1;
    for (std::size_t j = 0; j < res.nodes.size() && node < 0; ++j)
      if ((res.nodes[j] - centres[k]).head<2>().norm() < cfg.merge_distance_m &&
          std::abs(res.nodes[j].z() - centres[k].z()) <= 0.5 * cfg.height_m)
        node = static_cast<int>(j);
    if (node < 0) {
      node = static_cast<int>(res.nodes.size());
      res.nodes.push_back(centres[k]);
    }
    for (int q : owned[k])
      res.node_of_point[static_cast<std::size_t>(ipts[static_cast<std::size_t>(q)])] = node;
  }
  for (const auto& c : res.nodes) res.branches.push_back(branchesNode(c, s, nullptr));
  return res;
}

}  // namespace

}  // namespace slamroute::roadgraph
