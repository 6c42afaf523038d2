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
// western third of the graph off that way).
#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include "Streets.hpp"

namespace slamroute::roadgraph::detail {

bool splitAtPassedNode(const StreetContext& ctx, int c, const std::vector<int>& mem, int na, int nb,
                       std::vector<Street>& streets, GraphBuildStats& st) {
  const EdgeConfig& ec = ctx.ec;
  const std::vector<Point3>& sp = ctx.spts.pts;
  const std::vector<int>& label = ctx.spts.label;
  const std::vector<int>& subset_of = ctx.spts.subset_of;
  const PointGrid& sp_grid = ctx.sp_grid;
  const Traces& traces = ctx.traces;
  const std::vector<std::size_t>& order = ctx.order;
  const std::vector<int>& voxel_of = ctx.voxel_of;
  const std::vector<Point3>& nodes = ctx.nodes;
  const PointGrid& node_grid = ctx.node_grid;
  const std::size_t n_inter = ctx.n_inter;
  const double half_h = ctx.half_h;
  const double reach = ec.clear_radius_m + ec.cluster_tolerance_m;
  if (!ec.split_at_passed_nodes) return false;
  std::vector<double> best(n_inter, reach);
  std::vector<int> contact(n_inter, -1);
  for (int i : mem)
    node_grid.forEachNear(sp[static_cast<std::size_t>(i)], reach, half_h, [&](int j) {
      const auto J = static_cast<std::size_t>(j);
      if (J >= n_inter) return;
      const double d = (nodes[J] - sp[static_cast<std::size_t>(i)]).head<2>().norm();
      if (d < best[J]) {
        best[J] = d;
        contact[J] = i;
      }
    });
  std::vector<int> ends;
  for (std::size_t j = 0; j < n_inter; ++j)
    if (contact[j] >= 0) ends.push_back(static_cast<int>(j));
  if (ends.size() < 3) return false;
  std::vector<std::vector<double>> d(ends.size());
  for (std::size_t e = 0; e < ends.size(); ++e) {
    d[e].assign(sp.size(), std::numeric_limits<double>::infinity());
    geodesic(sp, sp_grid, label, c, ec.cluster_tolerance_m,
             contact[static_cast<std::size_t>(ends[e])], d[e]);
  }
  int centre = -1;
  double best_sum = std::numeric_limits<double>::infinity();
  for (int i : mem) {
    double sum = 0.0;
    for (const auto& de : d) sum += de[static_cast<std::size_t>(i)];
    if (sum < best_sum) {
      best_sum = sum;
      centre = i;
    }
  }
  if (centre < 0) return false;
  const auto C = static_cast<std::size_t>(centre);
  std::vector<std::size_t> branch;  // contacts at the end of a real branch
  std::size_t hub = ends.size();    // the passed node's contact
  for (std::size_t e = 0; e < ends.size(); ++e)
    if (d[e][C] >= ec.clear_radius_m)
      branch.push_back(e);
    else if (hub == ends.size() || d[e][C] < d[hub][C])
      hub = e;
  if (branch.size() < 2 || hub == ends.size() || ends[hub] == na || ends[hub] == nb) return false;
  // Evidence that the street joins the passed junction: vehicles that drive between the
  // cluster and a point well inside the node's cleared disk (clear_radius_m -
  // cluster_tolerance_m) with no other street point in between; GPS noise on a road merely
  // passing by only grazes the disk's rim.
  const Point3& hp = nodes[static_cast<std::size_t>(ends[hub])];
  const double deep = ec.clear_radius_m - ec.cluster_tolerance_m;
  std::set<int> drivers;
  bool from_cluster = false, via_hub = false;  // since the vehicle's last street point
  for (std::size_t k = 0; k < order.size(); ++k) {
    const auto& q = traces.points[order[k]];
    if (k > 0) {
      const auto& p = traces.points[order[k - 1]];
      if (p.vehicle != q.vehicle || q.t - p.t > ec.max_gap_s) from_cluster = via_hub = false;
    }
    const int sub = subset_of[static_cast<std::size_t>(voxel_of[order[k]])];
    if (sub >= 0) {
      const bool here = label[static_cast<std::size_t>(sub)] == c;
      if (here && via_hub) drivers.insert(q.vehicle);
      from_cluster = here;
      via_hub = false;
    } else if ((q.pos - hp).head<2>().norm() <= deep) {
      if (from_cluster) drivers.insert(q.vehicle);
      via_hub = true;
    }
  }
  if (static_cast<int>(drivers.size()) < ec.min_link_vehicles) return false;
  std::vector<std::vector<int>> part(branch.size());
  for (int i : mem) {
    std::size_t nearest = 0;
    for (std::size_t q = 1; q < branch.size(); ++q)
      if (d[branch[q]][static_cast<std::size_t>(i)] <
          d[branch[nearest]][static_cast<std::size_t>(i)])
        nearest = q;
    part[nearest].push_back(i);
  }
  ++st.passed_nodes;
  for (std::size_t q = 0; q < branch.size(); ++q) {
    if (static_cast<int>(part[q].size()) < ec.min_street_points) continue;
    Street s;
    s.members = part[q];
    s.centre = binnedCentre(sp, part[q], d[branch[q]], ec.polyline_step_m);
    if (s.centre.empty()) continue;
    s.u = ends[branch[q]];
    s.v = ends[hub];
    s.comp = c;
    streets.push_back(std::move(s));
  }
  return true;
}

}  // namespace slamroute::roadgraph::detail
