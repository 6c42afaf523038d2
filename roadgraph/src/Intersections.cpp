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
#include <numeric>
#include <stdexcept>
#include <unordered_map>

#include "DensestFirst.hpp"
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
using detail::DensestFirstGroup;
using detail::DensestFirstParams;
using detail::groupDensestFirst;
using detail::median;
using detail::PointGrid;
using detail::Scratch;

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
      return static_cast<std::uint64_t>(static_cast<std::int64_t>(std::floor(v / 32.0)) +
                                        (1 << 30));
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

/// The two hollow cylinders of one detection over the points in `grid`: the paper's ring and,
/// radii x wide_scale, a second one. At a big junction (4-lane avenues, a junction box of ~25 m)
/// turning traffic runs through the paper's 10-25 m ring and links the arms into one or two
/// clusters; a ring beyond the junction box still separates them. A point is an intersection
/// point when either ring sees >= min_branches; the ring seeing more branches is used for its
/// vote. Votes of points on an arm near a junction fall on the junction's centre, so the larger
/// ring adds evidence for junctions rather than new nodes.
struct Rings {
  const PointGrid& grid;
  const std::vector<Point3>& pts;
  const std::vector<Eigen::Vector2d>* axes;
  const NodeConfig& cfg;
  NodeConfig wide;

  Rings(const PointGrid& g, const std::vector<Point3>& p, const std::vector<Eigen::Vector2d>* a,
        const NodeConfig& c)
      : grid(g), pts(p), axes(a), cfg(c), wide(c) {
    wide.inner_radius_m *= c.wide_scale;
    wide.outer_radius_m *= c.wide_scale;
  }
  bool useWide() const { return cfg.wide_scale > 1.0; }
  const NodeConfig& ring(bool is_wide) const { return is_wide ? wide : cfg; }

  /// Branches at a trace point. The larger ring is only tried where the paper's ring holds
  /// points over a wide range of bearings (a street, straight or curved, covers two narrow
  /// sectors; a junction whose arms the ring sees linked covers most of the circle), which
  /// keeps its cost small.
  int atPoint(const Point3& c, Scratch& s, bool* is_wide) const {
    double coverage = 0.0;
    const int b1 = branchesAt(grid, pts, c, cfg, s, nullptr, &coverage);
    int b2 = 0;
    if (useWide() && b1 < cfg.min_branches && coverage >= cfg.wide_min_coverage_deg)
      b2 = branchesAt(grid, pts, c, wide, s, nullptr);
    if (is_wide) *is_wide = b2 > b1;
    return std::max(b1, b2);
  }
  /// Branches at a candidate node: both rings are always tried (a handful of tests, not one
  /// per point).
  int atNode(const Point3& c, Scratch& s, bool* is_wide) const {
    const int b1 = branchesAt(grid, pts, c, cfg, s, nullptr);
    const int b2 =
        useWide() && b1 < cfg.min_branches ? branchesAt(grid, pts, c, wide, s, nullptr) : 0;
    if (is_wide) *is_wide = b2 > b1;
    return std::max(b1, b2);
  }
};

using ThreadScratch = tbb::enumerable_thread_specific<Scratch>;

struct PointTests {
  std::vector<int> branches;  ///< per point, branches seen by the better ring
  std::vector<char> by_wide;  ///< per point, the wide ring saw more
};

/// Step 1: the hollow-cylinder test of every point (independent -> parallel, deterministic).
PointTests testEveryPoint(const Rings& rings, ThreadScratch& scratch) {
  const std::size_t n = rings.pts.size();
  PointTests t;
  t.branches.assign(n, 0);
  t.by_wide.assign(n, 0);
  Progress progress("intersections", n);
  const std::size_t chunk = 20000;
  for (std::size_t b = 0; b < n; b += chunk) {
    const std::size_t e = std::min(n, b + chunk);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(b, e, 256), [&](const auto& r) {
      Scratch& s = scratch.local();
      for (std::size_t i = r.begin(); i != r.end(); ++i) {
        bool w = false;
        t.branches[i] = rings.atPoint(rings.pts[i], s, &w);
        t.by_wide[i] = w ? 1 : 0;
      }
    });
    progress.update(e);
  }
  progress.finish();
  return t;
}

/// Step 2: each intersection point votes for its junction's centre, the least-squares crossing
/// of the branches it sees (re-evaluated at the crossing). Points anywhere in a junction's
/// intersection region (up to ~inner radius + road width from the centre) vote for the same
/// spot, so a wide junction is not split into several nodes; a point whose branches give no
/// stable crossing (near-parallel lines) votes for itself.
std::vector<Point3> centreVotes(const Rings& rings, const std::vector<int>& voters,
                                const std::vector<char>& by_wide, ThreadScratch& scratch) {
  const NodeConfig& cfg = rings.cfg;
  std::vector<Point3> votes(voters.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, voters.size(), 64), [&](const auto& r) {
    Scratch& s = scratch.local();
    for (std::size_t k = r.begin(); k != r.end(); ++k) {
      const auto i = static_cast<std::size_t>(voters[k]);
      const Point3& p = rings.pts[i];
      if (!crossingFrom(rings.grid, rings.pts, rings.axes, p, rings.ring(by_wide[i] != 0), s,
                        cfg.vote_iterations, cfg.vote_max_m, votes[k]))
        votes[k] = p;
    }
  });
  return votes;
}

/// Candidate nodes: a position and the votes (indices into the votes) it owns.
struct Candidates {
  std::vector<Point3> centres;
  std::vector<std::vector<int>> owned;
};

double medianGroupSize(const std::vector<DensestFirstGroup>& groups, int min_size) {
  std::vector<double> sizes;
  for (const auto& g : groups)
    if (static_cast<int>(g.members.size()) >= min_size)
      sizes.push_back(static_cast<double>(g.members.size()));
  return sizes.empty() ? 0.0 : median(sizes);
}

/// Step 4: one candidate per vote group at the median of its votes (optionally, refine_centre,
/// the crossing of the arms seen from there). The candidate must pass the test itself: a
/// fragment of intersection points on an arm (noise) sees only the two ways of its street from
/// its median. A strongly voted group need not (see Intersections.cpp's header).
Candidates nodeCandidates(const Rings& rings, std::vector<DensestFirstGroup> groups, Scratch& s) {
  const NodeConfig& cfg = rings.cfg;
  const double median_votes = medianGroupSize(groups, cfg.min_node_points);
  Candidates out;
  for (auto& g : groups) {
    const auto votes = static_cast<double>(g.members.size());
    if (static_cast<int>(g.members.size()) < cfg.min_node_points) continue;
    Point3 c = g.median;
    bool is_wide = false;
    const int b0 = rings.atNode(c, s, &is_wide);
    if (b0 < cfg.min_branches &&
        !(cfg.strong_vote_factor > 0.0 && votes >= cfg.strong_vote_factor * median_votes))
      continue;
    logDebug("node: vote median (" + std::to_string(c.x()) + ", " + std::to_string(c.y()) +
             ") from " + std::to_string(g.members.size()) + " votes, " + std::to_string(b0) +
             " branches");
    if (cfg.refine_centre) {
      // Keep the refined centre only when it still sees the junction's branches (curved arms
      // or wide junctions can mislead the line fit).
      Point3 cr;
      crossingFrom(rings.grid, rings.pts, rings.axes, c, rings.ring(is_wide), s, 3,
                   cfg.inner_radius_m, cr);
      if (rings.atNode(cr, s, nullptr) >= b0) c = cr;
    }
    out.centres.push_back(c);
    out.owned.push_back(std::move(g.members));
  }
  return out;
}

/// Step 5: candidates with fewer votes than min_vote_fraction of the median candidate's are
/// dropped. A junction driven through by traffic collects votes from its whole intersection
/// region (tens to hundreds of points); a bend of a wide road, a lane split or a noisy stretch
/// collects a handful. Relative to the median so it adapts to the survey's density.
void dropWeaklyVoted(Candidates& cands, double min_vote_fraction) {
  if (cands.centres.empty() || min_vote_fraction <= 0.0) return;
  std::vector<double> nv;
  for (const auto& o : cands.owned) nv.push_back(static_cast<double>(o.size()));
  const double need = min_vote_fraction * median(nv);
  std::size_t kept = 0;
  for (std::size_t k = 0; k < cands.centres.size(); ++k)
    if (static_cast<double>(cands.owned[k].size()) >= need) {
      if (kept != k) {  // a self-move would empty the vote list
        cands.centres[kept] = cands.centres[k];
        cands.owned[kept] = std::move(cands.owned[k]);
      }
      ++kept;
    }
  cands.centres.resize(kept);
  cands.owned.resize(kept);
}

/// Step 6: candidates closer than merge_distance_m are one junction (the ring cannot resolve
/// junctions much closer than its inner radius): strongest (most votes) first, a weaker
/// candidate near an accepted node is absorbed by it and keeps no position of its own. Fills
/// res.nodes and, for the voters (indices of the points), res.node_of_point.
void mergeCloseCandidates(const Candidates& cands, const std::vector<int>& voters,
                          const NodeConfig& cfg, IntersectionResult& res) {
  std::vector<std::size_t> by_votes(cands.centres.size());
  std::iota(by_votes.begin(), by_votes.end(), std::size_t{0});
  std::stable_sort(by_votes.begin(), by_votes.end(), [&](std::size_t a, std::size_t b) {
    return cands.owned[a].size() > cands.owned[b].size();
  });
  for (const std::size_t k : by_votes) {
    const Point3& c = cands.centres[k];
    int node = -1;
    for (std::size_t j = 0; j < res.nodes.size() && node < 0; ++j)
      if ((res.nodes[j] - c).head<2>().norm() < cfg.merge_distance_m &&
          std::abs(res.nodes[j].z() - c.z()) <= 0.5 * cfg.height_m)
        node = static_cast<int>(j);
    if (node < 0) {
      node = static_cast<int>(res.nodes.size());
      res.nodes.push_back(c);
    }
    for (const int q : cands.owned[k])
      res.node_of_point[static_cast<std::size_t>(voters[static_cast<std::size_t>(q)])] = node;
  }
}

IntersectionResult detectSorted(const std::vector<Point3>& pts, const NodeConfig& cfg,
                                const std::vector<Eigen::Vector2d>* axes) {
  if (!(cfg.inner_radius_m >= 0.0 && cfg.outer_radius_m > cfg.inner_radius_m &&
        cfg.height_m > 0.0 && cfg.cluster_tolerance_m > 0.0))
    throw std::invalid_argument(
        "roadgraph.nodes: need 0 <= inner_radius_m < outer_radius_m, height_m > 0, "
        "cluster_tolerance_m > 0");
  PointGrid grid(pts, 5.0);
  grid.linkWithin(cfg.cluster_tolerance_m);
  const Rings rings(grid, pts, axes, cfg);
  ThreadScratch scratch;
  IntersectionResult res;
  const PointTests tests = testEveryPoint(rings, scratch);
  res.is_intersection.assign(pts.size(), 0);
  res.node_of_point.assign(pts.size(), -1);
  std::vector<int> voters;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    res.is_intersection[i] = tests.branches[i] >= cfg.min_branches;
    if (res.is_intersection[i]) voters.push_back(static_cast<int>(i));
  }
  const std::vector<Point3> votes = centreVotes(rings, voters, tests.by_wide, scratch);
  // Step 3: vote groups around the densest places (votes within vote_radius_m), node_radius_m.
  const DensestFirstParams grouping{cfg.vote_radius_m, cfg.node_radius_m, 0.5 * cfg.height_m};
  Scratch s;
  Candidates cands = nodeCandidates(rings, groupDensestFirst(votes, grouping), s);
  dropWeaklyVoted(cands, cfg.min_vote_fraction);
  mergeCloseCandidates(cands, voters, cfg, res);
  for (const auto& c : res.nodes) res.branches.push_back(rings.atNode(c, s, nullptr));
  return res;
}

}  // namespace

}  // namespace slamroute::roadgraph
