// Streets that run through a junction (paper §3.1 step 2, a case the paper leaves open).
//
// A cluster that reaches the cleared disks of >= 3 nodes and passes one of them within
// clear_radius_m + cluster_tolerance_m (its branch point, the member with the least sum of
// geodesic distances to the contacts, is less than clear_radius_m from that node's contact)
// runs through that junction when at least min_link_vehicles vehicles drive from the cluster
// straight into the node's cleared disk: the node lies off the roads (big junctions, where the
// vote median is 15-30 m from where the arms meet) or the arm joining them was cleared. It
// becomes one street per branch, each ending at the passed node, unless the cluster's geodesic
// ends are attached to that node already. Without it, eqs. 1-2 at the geodesic ends join the
// two far contacts and the passed junction loses its arms (on Bologna, a big junction box cut the
// western third of the graph off that way). When no contact lies near the branch point, a node
// may still lie beside it (hubBesideBranchPoint).
// A geodesic end with no node near it (a dead end, e.g. at the border of the surveyed area) is
// the end of a branch too when the cluster reaches fewer than three nodes: a street from a dead
// end that bends round a junction to the next junction reaches only two, and unsplit it joins the
// dead end to the far junction past the junction it turns at (Braunschweig: two streets whose
// node lies 15 m off their bend). With three or more nodes the nodes alone place the branch
// point (the dead end of a long cluster that passes two junctions pulls the point of least sum
// of distances to the wrong one), but a dead end still ends a branch of its own: otherwise its
// arm's points go to the other branches and their streets run out along it (Bologna junction 9,
// whose western arm ends at the map border).
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
#include <set>

#include "Streets.hpp"

namespace slamroute::roadgraph::detail {
namespace {

/// The ends of the cluster's branches: the intersection nodes within reach of the cluster, each
/// with the member nearest to it, then, when fewer than three nodes are reached, the geodesic
/// ends without a node (dead ends).
struct Contacts {
  std::vector<int> ends;    ///< per contact, its node, or -1 for a dead end
  std::vector<int> member;  ///< per contact, its member
  std::size_t placing = 0;  ///< the first `placing` contacts place the branch point
};

Contacts nodeContacts(const StreetContext& ctx, const std::vector<int>& mem,
                      const std::vector<int>& dead_ends) {
  const std::vector<Point3>& sp = ctx.spts.pts;
  const double reach = ctx.ec.clear_radius_m + ctx.ec.cluster_tolerance_m;
  std::vector<double> best(ctx.n_inter, reach);
  std::vector<int> contact(ctx.n_inter, -1);
  for (int i : mem)
    ctx.node_grid.forEachNear(sp[static_cast<std::size_t>(i)], reach, ctx.half_h, [&](int j) {
      const auto J = static_cast<std::size_t>(j);
      if (J >= ctx.n_inter) return;
      const double d = (ctx.nodes[J] - sp[static_cast<std::size_t>(i)]).head<2>().norm();
      if (d < best[J]) {
        best[J] = d;
        contact[J] = i;
      }
    });
  Contacts c;
  for (std::size_t j = 0; j < ctx.n_inter; ++j)
    if (contact[j] >= 0) {
      c.ends.push_back(static_cast<int>(j));
      c.member.push_back(contact[j]);
    }
  // With three nodes or more a far dead end would pull the branch point off the hub: it only
  // ends a branch of its own.
  c.placing = c.ends.size() >= 3 ? c.ends.size() : c.ends.size() + dead_ends.size();
  for (int i : dead_ends) {
    c.ends.push_back(-1);
    c.member.push_back(i);
  }
  return c;
}

/// The branch point: the member with the least sum of geodesic distances to the contacts `use`.
int branchPoint(const std::vector<int>& mem, const std::vector<std::vector<double>>& d,
                const std::vector<std::size_t>& use) {
  int centre = -1;
  double best_sum = std::numeric_limits<double>::infinity();
  for (int i : mem) {
    double sum = 0.0;
    for (std::size_t e : use) sum += d[e][static_cast<std::size_t>(i)];
    if (sum < best_sum) {
      best_sum = sum;
      centre = i;
    }
  }
  return centre;
}

/// Vehicles that drive between cluster c and a point well inside the cleared disk of the node
/// at hp (clear_radius_m - cluster_tolerance_m) with no other street point in between; GPS noise
/// on a road merely passing by only grazes the disk's rim.
std::size_t vehiclesThroughNode(const StreetContext& ctx, int c, const Point3& hp) {
  const EdgeConfig& ec = ctx.ec;
  const Traces& traces = ctx.traces;
  const double deep = ec.clear_radius_m - ec.cluster_tolerance_m;
  std::set<int> drivers;
  bool from_cluster = false, via_hub = false;  // since the vehicle's last street point
  for (std::size_t k = 0; k < ctx.order.size(); ++k) {
    const auto& q = traces.points[ctx.order[k]];
    if (k > 0) {
      const auto& p = traces.points[ctx.order[k - 1]];
      if (p.vehicle != q.vehicle || q.t - p.t > ec.max_gap_s) from_cluster = via_hub = false;
    }
    const int sub = ctx.spts.subset_of[static_cast<std::size_t>(ctx.voxel_of[ctx.order[k]])];
    if (sub >= 0) {
      const bool here = ctx.spts.label[static_cast<std::size_t>(sub)] == c;
      if (here && via_hub) drivers.insert(q.vehicle);
      from_cluster = here;
      via_hub = false;
    } else if ((q.pos - hp).head<2>().norm() <= deep) {
      if (from_cluster) drivers.insert(q.vehicle);
      via_hub = true;
    }
  }
  return drivers.size();
}

/// Per branch, its members and their distances from its contact, which order its centreline.
/// A member lies on the arm whose contact it is nearer to than the branch point C is (least
/// d(contact, i) - d(contact, C)): on its own arm that difference is -d(C, i), on any other
/// +d(C, i). The plain nearest contact would hand the part of a long arm next to C to a short
/// arm, whose street then runs out along the long one and back. A member more than a clustering
/// step past C on every branch lies on an arm that ends at no contact (one carriageway of a
/// divided arm that joins the other only through the junction, Bologna junction 9): it belongs
/// to the arm it runs beside, the branch of the nearest member at least clear_radius_m inside
/// its arm by the first rule, at that member's distance (its own geodesic one runs round through
/// the junction).
struct BranchParts {
  std::vector<std::vector<int>> members;
  std::vector<std::vector<double>> dist;  ///< per branch, indexed by street point
};

BranchParts assignToBranches(const StreetContext& ctx, const std::vector<int>& mem,
                             const std::vector<std::vector<double>>& d,
                             const std::vector<std::size_t>& branch, std::size_t centre) {
  const std::vector<Point3>& sp = ctx.spts.pts;
  BranchParts out;
  out.members.resize(branch.size());
  for (std::size_t q = 0; q < branch.size(); ++q) out.dist.push_back(d[branch[q]]);
  std::vector<std::pair<int, std::size_t>> placed, apart, inside;  // (member, branch)
  for (int i : mem) {
    std::size_t nearest = 0;
    double least = std::numeric_limits<double>::infinity();
    for (std::size_t q = 0; q < branch.size(); ++q) {
      const double beyond = d[branch[q]][static_cast<std::size_t>(i)] - d[branch[q]][centre];
      if (beyond < least) {
        least = beyond;
        nearest = q;
      }
    }
    (least > ctx.ec.cluster_tolerance_m ? apart : placed).emplace_back(i, nearest);
    if (least <= -ctx.ec.clear_radius_m) inside.emplace_back(i, nearest);
  }
  for (auto& [i, q] : apart) {
    const Point3& p = sp[static_cast<std::size_t>(i)];
    double best = std::numeric_limits<double>::infinity();
    int beside = -1;
    for (const auto& [j, qj] : inside)
      if (const double dd = (sp[static_cast<std::size_t>(j)] - p).head<2>().squaredNorm();
          dd < best) {
        best = dd;
        beside = j;
        q = qj;
      }
    if (beside >= 0)
      out.dist[q][static_cast<std::size_t>(i)] = d[branch[q]][static_cast<std::size_t>(beside)];
  }
  for (const auto* list : {&placed, &apart})
    for (const auto& [i, q] : *list) out.members[q].push_back(i);
  return out;
}

/// One street per branch, each from the branch's node (-1 for a dead end, which the caller gives
/// an end node) to the passed node.
void streetsPerBranch(const StreetContext& ctx, int c, const Contacts& contacts,
                      const std::vector<int>& mem, const std::vector<std::vector<double>>& d,
                      const std::vector<std::size_t>& branch, std::size_t hub, std::size_t centre,
                      std::vector<Street>& streets) {
  const BranchParts parts = assignToBranches(ctx, mem, d, branch, centre);
  for (std::size_t q = 0; q < branch.size(); ++q) {
    const std::vector<int>& part = parts.members[q];
    if (static_cast<int>(part.size()) < ctx.ec.min_street_points) continue;
    Street s;
    s.members = part;
    s.centre = binnedCentre(ctx.spts.pts, part, parts.dist[q], ctx.ec.polyline_step_m);
    if (s.centre.empty()) continue;
    s.u = contacts.ends[branch[q]];
    s.v = contacts.ends[hub];
    s.comp = c;
    streets.push_back(std::move(s));
  }
}

/// Where the cluster branches beside a node it passes.
struct BesideHub {
  std::size_t centre = 0, hub = 0;
  std::vector<std::size_t> branch;
};

/// A big junction's node can lie beside the point where its arms meet (its vote 15-20 m off, at
/// another corner of the junction box), with its nearest street point on a carriageway that
/// joins the arms only far off, so no contact lies near the branch point (Bologna junction 9).
/// Then the node contact h whose node lies within attach_max_m of the branch point of the other
/// contacts (dead ends included, as h's arm is not there to place it) is the passed node, the
/// nearest such; the other contacts at least clear_radius_m from that point end branches.
std::optional<BesideHub> hubBesideBranchPoint(const StreetContext& ctx, const std::vector<int>& mem,
                                              const Contacts& contacts,
                                              const std::vector<std::vector<double>>& d) {
  std::optional<BesideHub> best;
  double best_dist = ctx.ec.attach_max_m;
  for (std::size_t h = 0; h < contacts.ends.size(); ++h) {
    if (contacts.ends[h] < 0) continue;
    std::vector<std::size_t> index;
    for (std::size_t e = 0; e < d.size(); ++e)
      if (e != h) index.push_back(e);
    const int centre = branchPoint(mem, d, index);
    if (centre < 0) continue;
    const auto C = static_cast<std::size_t>(centre);
    const Point3& node = ctx.nodes[static_cast<std::size_t>(contacts.ends[h])];
    const double dist = (ctx.spts.pts[C] - node).head<2>().norm();
    if (dist > best_dist) continue;
    BesideHub j{C, h, {}};
    for (std::size_t e : index)
      if (d[e][C] >= ctx.ec.clear_radius_m) j.branch.push_back(e);
    if (j.branch.size() < 2) continue;
    best_dist = dist;
    best = std::move(j);
  }
  return best;
}

}  // namespace

bool splitAtPassedNode(const StreetContext& ctx, int c, const Street& s, int na, int nb,
                       std::vector<Street>& streets, GraphBuildStats& st) {
  const EdgeConfig& ec = ctx.ec;
  if (!ec.split_at_passed_nodes) return false;
  const std::vector<int>& mem = s.members;
  std::vector<int> dead_ends;
  if (na < 0) dead_ends.push_back(s.a);
  if (nb < 0) dead_ends.push_back(s.b);
  const Contacts contacts = nodeContacts(ctx, mem, dead_ends);
  const std::vector<int>& ends = contacts.ends;
  if (contacts.placing < 3) return false;
  std::vector<std::vector<double>> d(ends.size());
  for (std::size_t e = 0; e < ends.size(); ++e) {
    d[e].assign(ctx.spts.pts.size(), std::numeric_limits<double>::infinity());
    geodesic(ctx.spts.pts, ctx.sp_grid, ctx.spts.label, c, ec.cluster_tolerance_m,
             contacts.member[e], d[e]);
  }
  std::vector<std::size_t> placing(contacts.placing);
  std::iota(placing.begin(), placing.end(), std::size_t{0});
  const int centre = branchPoint(mem, d, placing);
  if (centre < 0) return false;
  auto C = static_cast<std::size_t>(centre);
  std::vector<std::size_t> branch;  // contacts at the end of a real branch
  std::size_t hub = ends.size();    // the passed node's contact
  for (std::size_t e = 0; e < ends.size(); ++e)
    if (d[e][C] >= ec.clear_radius_m)
      branch.push_back(e);
    else if (ends[e] >= 0 && (hub == ends.size() || d[e][C] < d[hub][C]))
      hub = e;
  if (hub == ends.size())
    if (const auto beside = hubBesideBranchPoint(ctx, mem, contacts, d)) {
      C = beside->centre;
      hub = beside->hub;
      branch = beside->branch;
    }
  if (branch.size() < 2 || hub == ends.size() || ends[hub] == na || ends[hub] == nb) return false;
  const Point3& hp = ctx.nodes[static_cast<std::size_t>(ends[hub])];
  if (static_cast<int>(vehiclesThroughNode(ctx, c, hp)) < ec.min_link_vehicles) return false;
  ++st.passed_nodes;
  streetsPerBranch(ctx, c, contacts, mem, d, branch, hub, C, streets);
  return true;
}

}  // namespace slamroute::roadgraph::detail
