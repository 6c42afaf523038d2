// Streets (paper §3.1 steps 2-3): remove the trace points near the nodes, cluster the rest, and
// attach each cluster to its two nearest nodes (eqs. 1-2).
//
// Choices the paper leaves open (documented here, configurable in EdgeConfig):
// - "Node points and their neighbourhood" = trace points within clear_radius_m (horizontal, and
//   within half the cylinder height) of a node. 12 m: just beyond the 10 m inner radius, so the
//   arms of a junction fall apart, while streets shorter than 24 m between junctions survive.
// - Eqs. 1-2 (the two nodes nearest to any point of the street) are evaluated at the street's two
//   geodesic ends only, so a street passing close to another junction is not attached to it. A
//   street end with no node within attach_max_m is a dead end and gets an end node there.
// - Leftover pieces whose both ends lie near the same node (corner cuts inside a junction) are
//   dropped; they are not streets. Unless the piece also reaches, at least clear_radius_m from
//   both ends, the cleared disk of another node: then it is a street whose two directions are
//   separate lanes a few metres apart, linked into one U-shaped cluster only near the far
//   junction (Bologna has 3 such streets), and it runs from its ends' node to that one.
// - A cluster that runs through a junction whose node lies 12-16 m off it (not cleared there) is
//   split at that node when vehicles drive from it into the node's disk (splitAtPassedNode).
#include <algorithm>
#include <cmath>
#include <limits>

#include "Streets.hpp"

namespace slamroute::roadgraph::detail {
namespace {

struct Contact {
  int member = -1;  ///< street point (subset index) closest to the node
  int node = -1;
};

/// The bend of a U-shaped street cluster whose two geodesic ends `pa`, `pb` lie at node `both`:
/// the member closest to another intersection node, within the cleared radius plus one clustering
/// step of it and at least clear_radius_m from both ends, so a corner cut inside a junction
/// (short, all its points near its node) is not taken for a street.
Contact farContact(const std::vector<Point3>& sp, const std::vector<int>& members, const Point3& pa,
                   const Point3& pb, const std::vector<Point3>& nodes, std::size_t n_inter,
                   int both, const EdgeConfig& ec, double half_h) {
  const double reach = ec.clear_radius_m + ec.cluster_tolerance_m;
  Contact best;
  double best_d = reach;
  for (int i : members) {
    const Point3& p = sp[static_cast<std::size_t>(i)];
    if ((p - pa).head<2>().norm() < ec.clear_radius_m ||
        (p - pb).head<2>().norm() < ec.clear_radius_m)
      continue;
    for (std::size_t j = 0; j < n_inter; ++j) {
      if (static_cast<int>(j) == both || std::abs(nodes[j].z() - p.z()) > half_h) continue;
      const double d = (nodes[j] - p).head<2>().norm();
      if (d < best_d) {
        best_d = d;
        best = {i, static_cast<int>(j)};
      }
    }
  }
  return best;
}

}  // namespace

StreetPoints clearNodeNeighbourhoods(const std::vector<Point3>& voxels,
                                     const std::vector<Point3>& nodes, const EdgeConfig& ec,
                                     double half_h) {
  StreetPoints out;
  const PointGrid node_grid(nodes, std::max(ec.clear_radius_m, 1.0));
  out.subset_of.assign(voxels.size(), -1);
  for (std::size_t i = 0; i < voxels.size(); ++i) {
    bool near = false;
    node_grid.forEachNear(voxels[i], ec.clear_radius_m, half_h, [&](int) { near = true; });
    if (near) continue;
    out.subset_of[i] = static_cast<int>(out.pts.size());
    out.pts.push_back(voxels[i]);
  }
  int ncomp = 0;
  out.label = euclideanComponents(out.pts, ec.cluster_tolerance_m, &ncomp);
  out.comps.resize(static_cast<std::size_t>(ncomp));
  for (std::size_t k = 0; k < out.pts.size(); ++k)
    out.comps[static_cast<std::size_t>(out.label[k])].push_back(static_cast<int>(k));
  return out;
}

namespace {

/// Eqs. 1-2: the intersection node nearest to p within attach_max_m (not `exclude`), -1 if none.
int nearestNode(const StreetContext& ctx, const Point3& p, int exclude) {
  int best = -1;
  double bd = ctx.ec.attach_max_m;
  for (std::size_t j = 0; j < ctx.n_inter; ++j) {
    const Point3& n = ctx.nodes[j];
    if (static_cast<int>(j) == exclude || std::abs(n.z() - p.z()) > ctx.half_h) continue;
    const double d = (n - p).head<2>().norm();
    if (d <= bd) {
      bd = d;
      best = static_cast<int>(j);
    }
  }
  return best;
}

/// The member of cluster c geodesically farthest from src; dist holds the distances from src.
int farthestMember(const StreetContext& ctx, int c, const std::vector<int>& mem, int src,
                   std::vector<double>& dist) {
  for (int i : mem) dist[static_cast<std::size_t>(i)] = std::numeric_limits<double>::infinity();
  geodesic(ctx.spts.pts, ctx.sp_grid, ctx.spts.label, c, ctx.ec.cluster_tolerance_m, src, dist);
  int best = src;
  for (int i : mem)
    if (std::isfinite(dist[static_cast<std::size_t>(i)]) &&
        dist[static_cast<std::size_t>(i)] > dist[static_cast<std::size_t>(best)])
      best = i;
  return best;
}

/// Both ends of street s nearest to one node: the end farther from it goes to its next nearest
/// node. With none there, a street whose two directions are separate lanes a few metres apart,
/// linked only near its far junction, is one U-shaped cluster whose legs both end at the near
/// node: it runs from there to the other node its bend touches. False for a corner cut or a loop
/// (not a street).
bool attachBothEndsAtOneNode(const StreetContext& ctx, int c, Street& s, int& na, int& nb,
                             std::vector<double>& dist, GraphBuildStats& st) {
  const std::vector<Point3>& sp = ctx.spts.pts;
  const Point3 pa = sp[static_cast<std::size_t>(s.a)], pb = sp[static_cast<std::size_t>(s.b)];
  const int both = na;
  const double da = (ctx.nodes[static_cast<std::size_t>(na)] - pa).head<2>().norm();
  const double db = (ctx.nodes[static_cast<std::size_t>(na)] - pb).head<2>().norm();
  if (da <= db)
    nb = nearestNode(ctx, pb, na);
  else
    na = nearestNode(ctx, pa, nb);
  if (na >= 0 && nb >= 0) return true;
  const Contact far =
      farContact(sp, s.members, pa, pb, ctx.nodes, ctx.n_inter, both, ctx.ec, ctx.half_h);
  if (far.member < 0) {
    ++st.dropped_fragments;
    return false;
  }
  ++st.u_turn_streets;
  s.a = far.member;
  s.b = farthestMember(ctx, c, s.members, s.a, dist);
  na = far.node;
  nb = both;
  return true;
}

/// The members on the way between the street's ends a and b, `from_a` holding the geodesic
/// distances from a. A member whose way a -> it -> b is more than centreline_branch_max_m longer
/// than the street lies on a side branch: one direction's lane of an arm, a few metres from the
/// other and joined to the cluster only at the far junction, which the distances from a reach
/// the long way round. Binned with the rest, its points would share bins with the next stretch
/// of the street and pull the centreline diagonally across the block.
std::vector<int> membersAlongStreet(const StreetContext& ctx, int c, const Street& s,
                                    const std::vector<double>& from_a,
                                    std::vector<double>& from_b) {
  const auto at = [](const std::vector<double>& d, int i) {
    return d[static_cast<std::size_t>(i)];
  };
  for (int i : s.members)
    from_b[static_cast<std::size_t>(i)] = std::numeric_limits<double>::infinity();
  geodesic(ctx.spts.pts, ctx.sp_grid, ctx.spts.label, c, ctx.ec.cluster_tolerance_m, s.b, from_b);
  const double street = at(from_a, s.b) + ctx.ec.centreline_branch_max_m;
  std::vector<int> along;
  along.reserve(s.members.size());
  for (int i : s.members)
    if (at(from_a, i) + at(from_b, i) <= street) along.push_back(i);
  return along;
}

/// Dead ends get an end node at the last centreline point.
int endNode(GraphNodes& gn, const Point3& p, GraphBuildStats& st) {
  gn.pos.push_back(p);
  gn.is_end.push_back(1);
  ++st.dead_ends;
  return static_cast<int>(gn.pos.size()) - 1;
}

}  // namespace

std::vector<Street> attachStreets(const StreetPoints& spts, const Traces& traces,
                                  const std::vector<std::size_t>& order,
                                  const std::vector<int>& voxel_of, GraphNodes& gn,
                                  const EdgeConfig& ec, double half_h, GraphBuildStats& st) {
  const std::vector<Point3>& sp = spts.pts;
  // Over the intersection nodes (end nodes are appended below; the grid only knows the first
  // n_inter).
  const PointGrid node_grid(gn.pos, std::max(ec.clear_radius_m, 1.0));
  const PointGrid sp_grid(sp, std::max(ec.cluster_tolerance_m, 0.1));
  std::vector<double> dist(sp.size(), std::numeric_limits<double>::infinity());
  std::vector<double> from_b(sp.size(), std::numeric_limits<double>::infinity());
  std::vector<Street> streets;
  const StreetContext ctx{spts,   sp_grid,   traces,     order, voxel_of,
                          gn.pos, node_grid, gn.n_inter, ec,    half_h};
  for (int c = 0; c < static_cast<int>(spts.comps.size()); ++c) {
    const auto& mem = spts.comps[static_cast<std::size_t>(c)];
    if (static_cast<int>(mem.size()) < ec.min_street_points) continue;
    Street s;
    s.members = mem;
    s.a = farthestMember(ctx, c, mem, mem.front(), dist);
    s.b = farthestMember(ctx, c, mem, s.a, dist);  // dist now holds geodesic distances from a
    // Eqs. 1-2 at the street's ends: nearest node j, then nearest node k != j.
    int na = nearestNode(ctx, sp[static_cast<std::size_t>(s.a)], -1);
    int nb = nearestNode(ctx, sp[static_cast<std::size_t>(s.b)], -1);
    const std::size_t before = streets.size();
    if (splitAtPassedNode(ctx, c, s, na, nb, streets, st)) {
      for (std::size_t k = before; k < streets.size(); ++k)
        if (streets[k].u < 0) streets[k].u = endNode(gn, streets[k].centre.front(), st);
      continue;
    }
    // Centreline from a to b: centroids of geodesic-distance bins. A U-shaped cluster (both
    // ends at one node) keeps both legs: each leg's points lie at their distance from the bend.
    const bool u_shaped = na >= 0 && na == nb;
    if (u_shaped && !attachBothEndsAtOneNode(ctx, c, s, na, nb, dist, st)) continue;
    const std::vector<int> binned = u_shaped ? mem : membersAlongStreet(ctx, c, s, dist, from_b);
    s.centre = binnedCentre(sp, binned, dist, ec.polyline_step_m);
    if (s.centre.empty()) continue;
    s.u = na >= 0 ? na : endNode(gn, s.centre.front(), st);
    s.v = nb >= 0 ? nb : endNode(gn, s.centre.back(), st);
    s.comp = c;
    streets.push_back(std::move(s));
  }
  return streets;
}

}  // namespace slamroute::roadgraph::detail
