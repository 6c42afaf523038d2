// Paper §3.1 steps 2-3: streets and the graph.
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
//   junction (Bologna: 3 such streets were lost), and it runs from its ends' node to that one.
// - A cluster that runs through a junction whose node lies 12-16 m off it (not cleared there) is
//   split at that node when vehicles drive from it into the node's disk (splitAtPassedNode).
// - Junctions closer than about 2 x clear_radius_m lose their street with the clearing; vehicles
//   that drive straight from one junction into the other give that link (ShortLinks.cpp).
// - Centreline: points are ordered by geodesic distance (Dijkstra over the cluster's
//   neighbourhood graph) from one end and averaged in polyline_step_m bins; robust to GPS noise
//   across the road and to curves.
// - Direction of travel: each vehicle's consecutive points on a street form a run; a run that
//   advances more than min_run_m along the centreline counts for that direction. A street with
//   runs in one direction only is one-way (one directed edge); with both, or with no usable run
//   (then logged), it is two-way (two RoadEdges sharing `street`). On streets shorter than
//   2 x (clear_radius_m + min_run_m) drives from one end node to the other count as runs too.
#include "slamroute/roadgraph/GraphBuilder.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <queue>
#include <set>
#include <stdexcept>

#include "PointGrid.hpp"
#include "ShortLinks.hpp"
#include "slamroute/core/Log.hpp"
#include "slamroute/roadgraph/Intersections.hpp"

namespace slamroute::roadgraph {
namespace {

using detail::PointGrid;

struct Street {
  std::vector<int> members;  ///< indices into the street point subset
  Polyline centre;           ///< ordered A -> B, without node positions
  int a = -1, b = -1;        ///< end points (subset indices)
  int u = -1, v = -1;        ///< node ids (end nodes appended after intersections)
  int comp = -1;             ///< street cluster label, -1 for a short link
  int link_fwd = 0, link_bwd = 0;  ///< short link: vehicles driving u -> v and v -> u
};

/// Arc-length position of the projection of p on a polyline.
double arcPosition(const Polyline& pl, const Point3& p) {
  double best = std::numeric_limits<double>::infinity(), best_s = 0.0, s = 0.0;
  for (std::size_t i = 0; i + 1 < pl.size(); ++i) {
    const Vec3 d = pl[i + 1] - pl[i];
    const double len = d.norm();
    const double t = len > 1e-9 ? std::clamp((p - pl[i]).dot(d) / (len * len), 0.0, 1.0) : 0.0;
    const double dist = (pl[i] + t * d - p).squaredNorm();
    if (dist < best) {
      best = dist;
      best_s = s + t * len;
    }
    s += len;
  }
  return best_s;
}

/// Geodesic (Dijkstra) distances from `src` within one street cluster; dist is indexed by subset
/// index and only entries of `members` are touched.
void geodesic(const std::vector<Point3>& pts, const PointGrid& grid, const std::vector<int>& label,
              int comp, double tol, int src, std::vector<double>& dist) {
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> pq;
  dist[static_cast<std::size_t>(src)] = 0.0;
  pq.emplace(0.0, src);
  const double tol2 = tol * tol;
  while (!pq.empty()) {
    const auto [d, i] = pq.top();
    pq.pop();
    if (d > dist[static_cast<std::size_t>(i)]) continue;
    const Point3& p = pts[static_cast<std::size_t>(i)];
    grid.forEachNear(p, tol, tol, [&](int j) {
      if (label[static_cast<std::size_t>(j)] != comp) return;
      const double d2 = (pts[static_cast<std::size_t>(j)] - p).squaredNorm();
      if (d2 > tol2) return;
      const double nd = d + std::sqrt(d2);
      if (nd < dist[static_cast<std::size_t>(j)]) {
        dist[static_cast<std::size_t>(j)] = nd;
        pq.emplace(nd, j);
      }
    });
  }
}

/// Centreline of `members` ordered by `d` (geodesic distance from one end): centroids of
/// step_m bins; robust to GPS noise across the road and to curves.
Polyline binnedCentre(const std::vector<Point3>& sp, const std::vector<int>& members,
                      const std::vector<double>& d, double step_m) {
  double total = 0.0;
  for (int i : members)
    if (std::isfinite(d[static_cast<std::size_t>(i)]))
      total = std::max(total, d[static_cast<std::size_t>(i)]);
  const int nbins = std::max(1, static_cast<int>(std::ceil(total / step_m)));
  std::vector<Point3> bsum(static_cast<std::size_t>(nbins) + 1, Point3::Zero());
  std::vector<int> bcnt(static_cast<std::size_t>(nbins) + 1, 0);
  for (int i : members) {
    const double di = d[static_cast<std::size_t>(i)];
    if (!std::isfinite(di)) continue;
    const auto bin = static_cast<std::size_t>(std::min(nbins, static_cast<int>(di / step_m)));
    bsum[bin] += sp[static_cast<std::size_t>(i)];
    ++bcnt[bin];
  }
  Polyline centre;
  for (std::size_t k = 0; k < bsum.size(); ++k)
    if (bcnt[k] > 0) centre.push_back(bsum[k] / bcnt[k]);
  return centre;
}

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

/// Dead ends within `radius` of each other (and at one height) become one node at their mean:
/// two streets whose ends nearly touch meet there, e.g. at a corner no survey vehicle drove
/// round (each street then looks like a dead end). Streets left with both ends on one node are
/// dropped; end nodes that lose all streets stay and are dropped later as isolated.
void mergeNearbyEnds(std::vector<Point3>& nodes, const std::vector<char>& is_end, double radius,
                     double half_h, std::vector<Street>& streets, GraphBuildStats& st) {
  if (radius <= 0) return;
  std::vector<std::size_t> root(nodes.size());
  std::iota(root.begin(), root.end(), 0);
  auto find = [&](std::size_t i) {
    while (root[i] != i) i = root[i] = root[root[i]];
    return i;
  };
  for (std::size_t i = 0; i < nodes.size(); ++i)
    for (std::size_t j = i + 1; j < nodes.size(); ++j)
      if (is_end[i] && is_end[j] && (nodes[i] - nodes[j]).head<2>().norm() <= radius &&
          std::abs(nodes[i].z() - nodes[j].z()) <= half_h)
        root[find(j)] = find(i);
  std::vector<Point3> sum(nodes.size(), Point3::Zero());
  std::vector<int> cnt(nodes.size(), 0);
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (!is_end[i]) continue;
    sum[find(i)] += nodes[i];
    ++cnt[find(i)];
  }
  for (std::size_t i = 0; i < nodes.size(); ++i)
    if (is_end[i] && find(i) == i && cnt[i] > 1) {
      nodes[i] = sum[i] / cnt[i];
      st.dead_ends -= static_cast<std::size_t>(cnt[i] - 1);
      ++st.merged_end_pairs;
    }
  std::vector<Street> kept;
  for (auto& s : streets) {
    s.u = static_cast<int>(find(static_cast<std::size_t>(s.u)));
    s.v = static_cast<int>(find(static_cast<std::size_t>(s.v)));
    if (s.u == s.v) {
      ++st.dropped_fragments;
      continue;
    }
    kept.push_back(std::move(s));
  }
  streets = std::move(kept);
}

}  // namespace

GraphBuildResult buildRoadGraph(const Traces& traces, const Config& cfg) {
  const auto t0 = std::chrono::steady_clock::now();
  checkTraces(traces, traces.source.empty() ? "traces" : traces.source);
  const std::string where = traces.source.empty() ? "traces" : traces.source;
  const EdgeConfig& ec = cfg.edges;
  if (!(ec.clear_radius_m > 0 && ec.cluster_tolerance_m > 0 && ec.polyline_step_m > 0))
    throw std::invalid_argument("roadgraph.edges: radii, tolerance and step must be > 0");
  GraphBuildResult out;
  auto& st = out.stats;
  st.trace_points = traces.points.size();

  std::vector<Point3> raw;
  raw.reserve(traces.points.size());
  for (const auto& p : traces.points) raw.push_back(p.pos);
  const std::vector<Vec3> travel =
      travelDirections(traces, cfg.nodes.travel_span_m, cfg.edges.max_gap_s);
  const Downsampled ds = downsample(raw, cfg.nodes.downsample_m, &travel);
  st.voxels = ds.points.size();
  logInfo("build-graph: " + std::to_string(raw.size()) + " trace points -> " +
          std::to_string(ds.points.size()) + " voxels");

  // Step 1: nodes (hollow cylinder).
  const IntersectionResult ir = detectIntersections(ds.points, cfg.nodes, &ds.axes);
  st.intersection_points = static_cast<std::size_t>(
      std::count(ir.is_intersection.begin(), ir.is_intersection.end(), 1));
  if (ir.nodes.empty())
    throw std::runtime_error(where +
                             ": no intersection found in the traces (no point sees >= " +
                             std::to_string(cfg.nodes.min_branches) +
                             " branches in the hollow cylinder); a road graph needs junctions");
  std::vector<Point3> nodes = ir.nodes;
  const std::size_t n_inter = nodes.size();

  // Step 2: remove node neighbourhoods, cluster the rest into streets.
  const double half_h = 0.5 * cfg.nodes.height_m;
  const PointGrid node_grid(nodes, std::max(ec.clear_radius_m, 1.0));
  std::vector<int> subset_of(ds.points.size(), -1);
  std::vector<Point3> sp;
  std::vector<int> sp_voxel;
  for (std::size_t i = 0; i < ds.points.size(); ++i) {
    bool near = false;
    node_grid.forEachNear(ds.points[i], ec.clear_radius_m, half_h, [&](int) { near = true; });
    if (near) continue;
    subset_of[i] = static_cast<int>(sp.size());
    sp.push_back(ds.points[i]);
    sp_voxel.push_back(static_cast<int>(i));
  }
  int ncomp = 0;
  const std::vector<int> label = detail::euclideanComponents(sp, ec.cluster_tolerance_m, &ncomp);
  std::vector<std::vector<int>> comps(static_cast<std::size_t>(ncomp));
  for (std::size_t k = 0; k < sp.size(); ++k)
    comps[static_cast<std::size_t>(label[k])].push_back(static_cast<int>(k));

  auto nearestNode = [&](const Point3& p, int exclude) {
    int best = -1;
    double bd = ec.attach_max_m;
    for (std::size_t j = 0; j < n_inter; ++j) {
      if (static_cast<int>(j) == exclude || std::abs(nodes[j].z() - p.z()) > half_h) continue;
      const double d = (nodes[j] - p).head<2>().norm();
      if (d <= bd) {
        bd = d;
        best = static_cast<int>(j);
      }
    }
    return best;
  };

  // Trace points by vehicle, then time.
  std::vector<std::size_t> order(traces.points.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const auto &pa = traces.points[a], &pb = traces.points[b];
    return pa.vehicle != pb.vehicle ? pa.vehicle < pb.vehicle : pa.t < pb.t;
  });
  const PointGrid sp_grid(sp, std::max(ec.cluster_tolerance_m, 0.1));
  std::vector<double> dist(sp.size(), std::numeric_limits<double>::infinity());
  std::vector<Street> streets;
  std::vector<char> is_end(nodes.size(), 0);  // per node: a dead end (not an intersection)
  // A cluster that reaches the cleared disks of >= 3 nodes and passes one of them within
  // clear_radius_m + cluster_tolerance_m (its branch point, the member with the least sum of
  // geodesic distances to the contacts, is less than clear_radius_m from that node's contact)
  // runs through that junction when at least min_link_vehicles vehicles drive from the cluster
  // straight into the node's cleared disk: the node lies off the roads (big junctions, where the
  // vote median is 15-30 m from where the arms meet) or the arm joining them was cleared. It
  // becomes one street per branch, each ending at the passed node, unless the cluster's geodesic
  // ends are attached to that node already. Without it, eqs. 1-2 at the geodesic ends join the
  // two far contacts and the passed junction loses its arms (Bologna junction 15).
  const double reach = ec.clear_radius_m + ec.cluster_tolerance_m;
  auto splitAtPassedNode = [&](int c, const std::vector<int>& mem, int na, int nb) {
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
      const int sub = subset_of[static_cast<std::size_t>(ds.voxel_of[order[k]])];
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
  };
  for (int c = 0; c < ncomp; ++c) {
    const auto& mem = comps[static_cast<std::size_t>(c)];
    if (static_cast<int>(mem.size()) < ec.min_street_points) continue;
    auto farthest = [&](int src) {
      for (int i : mem) dist[static_cast<std::size_t>(i)] = std::numeric_limits<double>::infinity();
      geodesic(sp, sp_grid, label, c, ec.cluster_tolerance_m, src, dist);
      int best = src;
      for (int i : mem)
        if (std::isfinite(dist[static_cast<std::size_t>(i)]) &&
            dist[static_cast<std::size_t>(i)] > dist[static_cast<std::size_t>(best)])
          best = i;
      return best;
    };
    Street s;
    s.members = mem;
    s.a = farthest(mem.front());
    s.b = farthest(s.a);  // dist now holds geodesic distances from a
    const Point3 pa = sp[static_cast<std::size_t>(s.a)], pb = sp[static_cast<std::size_t>(s.b)];
    // Eqs. 1-2 at the street's ends: nearest node j, then nearest node k != j.
    int na = nearestNode(pa, -1), nb = nearestNode(pb, -1);
    if (splitAtPassedNode(c, mem, na, nb)) continue;
    if (na >= 0 && na == nb) {
      const int both = na;
      const double da = (nodes[static_cast<std::size_t>(na)] - pa).head<2>().norm();
      const double db = (nodes[static_cast<std::size_t>(na)] - pb).head<2>().norm();
      if (da <= db) nb = nearestNode(pb, na); else na = nearestNode(pa, nb);
      if (na < 0 || nb < 0) {
        // Both ends at one node. A street whose two directions are separate lanes a few metres
        // apart, linked only near its far junction, is one U-shaped cluster whose legs both end
        // at the near node: the street runs from there to the other node its bend touches.
        const Contact far = farContact(sp, mem, pa, pb, nodes, n_inter, both, ec, half_h);
        if (far.member < 0) {  // a corner cut or a loop, not a street
          ++st.dropped_fragments;
          continue;
        }
        ++st.u_turn_streets;
        s.a = far.member;
        s.b = farthest(s.a);
        na = far.node;
        nb = both;
      }
    }
    // Centreline from a to b: centroids of geodesic-distance bins.
    s.centre = binnedCentre(sp, mem, dist, ec.polyline_step_m);
    if (s.centre.empty()) continue;
    // Dead ends get an end node at the last centreline point.
    auto endNode = [&](const Point3& p) {
      nodes.push_back(p);
      is_end.push_back(1);
      ++st.dead_ends;
      return static_cast<int>(nodes.size()) - 1;
    };
    s.u = na >= 0 ? na : endNode(s.centre.front());
    s.v = nb >= 0 ? nb : endNode(s.centre.back());
    s.comp = c;
    streets.push_back(std::move(s));
  }
  mergeNearbyEnds(nodes, is_end, ec.end_merge_m, half_h, streets, st);
  st.streets = streets.size();
  std::vector<int> street_of_sp(sp.size(), -1);
  for (std::size_t k = 0; k < streets.size(); ++k)
    for (int i : streets[k].members)
      street_of_sp[static_cast<std::size_t>(i)] = static_cast<int>(k);

  // Full polylines node u -> node v.
  std::vector<Polyline> polys;
  for (const auto& s : streets) {
    Polyline pl;
    // Intersections, and dead ends moved by a merge, are not on the centreline yet.
    const Point3 &nu = nodes[static_cast<std::size_t>(s.u)], &nv = nodes[static_cast<std::size_t>(s.v)];
    if ((nu - s.centre.front()).norm() > 0.5) pl.push_back(nu);
    pl.insert(pl.end(), s.centre.begin(), s.centre.end());
    if ((nv - s.centre.back()).norm() > 0.5) pl.push_back(nv);
    if (pl.size() < 2) pl.push_back(pl.back());
    polys.push_back(std::move(pl));
  }

  // Directions of travel from each vehicle's runs along a street.
  std::vector<int> street_of_point(traces.points.size(), -1);
  for (std::size_t i = 0; i < traces.points.size(); ++i) {
    const int k = subset_of[static_cast<std::size_t>(ds.voxel_of[i])];
    if (k >= 0) street_of_point[i] = street_of_sp[static_cast<std::size_t>(k)];
  }
  // Drives from junction to junction (ShortLinks.cpp): links between junctions whose street the
  // clearing removed, and directions of travel on streets too short for runs to show them.
  const detail::Passages passages =
      detail::junctionPassages(traces, order, street_of_point, nodes, n_inter, ec, half_h);
  if (ec.link_max_m > 0) {
    std::set<std::pair<int, int>> linked;
    for (const auto& s : streets) linked.emplace(std::min(s.u, s.v), std::max(s.u, s.v));
    std::map<std::pair<int, int>, Street> links;
    for (const auto& [key, vehicles] : passages) {
      const auto [from, to, street] = key;
      const int a = std::min(from, to), b = std::max(from, to);
      if (street >= 0 || vehicles < ec.min_link_vehicles || linked.count({a, b}) ||
          (nodes[static_cast<std::size_t>(a)] - nodes[static_cast<std::size_t>(b)])
                  .head<2>()
                  .norm() > ec.link_max_m)
        continue;
      Street& l = links[{a, b}];
      l.u = a;
      l.v = b;
      (from == a ? l.link_fwd : l.link_bwd) = vehicles;
    }
    for (auto& [key, l] : links) {
      polys.push_back({nodes[static_cast<std::size_t>(l.u)], nodes[static_cast<std::size_t>(l.v)]});
      streets.push_back(std::move(l));
      ++st.short_links;
    }
    st.streets = streets.size();
  }
  std::vector<int> fwd(streets.size(), 0), bwd(streets.size(), 0);
  for (std::size_t k = 0; k < streets.size(); ++k)
    if (streets[k].comp < 0) {
      fwd[k] = streets[k].link_fwd >= ec.min_link_vehicles ? ec.min_direction_runs : 0;
      bwd[k] = streets[k].link_bwd >= ec.min_link_vehicles ? ec.min_direction_runs : 0;
    }
  // A street's points start clear_radius_m from its nodes, so on a street shorter than about
  // 2 x (clear_radius_m + min_run_m) few runs progress min_run_m: drives from one of its nodes to
  // the other over its points count too.
  for (const auto& [key, vehicles] : passages) {
    const auto [from, to, k] = key;
    if (k < 0 || vehicles < ec.min_link_vehicles) continue;
    const Street& s = streets[static_cast<std::size_t>(k)];
    if (polylineLength(polys[static_cast<std::size_t>(k)]) >=
        2 * (ec.clear_radius_m + ec.min_run_m))
      continue;
    if (from == s.u && to == s.v) fwd[static_cast<std::size_t>(k)] += vehicles;
    if (from == s.v && to == s.u) bwd[static_cast<std::size_t>(k)] += vehicles;
  }
  // A run counts in each direction it progresses along the street by `need`: a vehicle that
  // drives into a dead end and turns round there travels it both ways in one run.
  auto closeRun = [&](int s, std::size_t k_first, std::size_t k_last) {
    if (s < 0 || k_first == k_last) return;
    const auto& pl = polys[static_cast<std::size_t>(s)];
    const double len = polylineLength(pl);
    const double need = std::min(ec.min_run_m, 0.4 * len);
    double lo = std::numeric_limits<double>::infinity(), hi = -lo, rise = 0.0, fall = 0.0;
    for (std::size_t k = k_first; k <= k_last; ++k) {
      const double a = arcPosition(pl, traces.points[order[k]].pos);
      lo = std::min(lo, a);
      hi = std::max(hi, a);
      rise = std::max(rise, a - lo);
      fall = std::max(fall, hi - a);
    }
    if (rise > need) ++fwd[static_cast<std::size_t>(s)];
    if (fall > need) ++bwd[static_cast<std::size_t>(s)];
  };
  std::size_t run_first = 0;
  for (std::size_t k = 1; k <= order.size(); ++k) {
    const std::size_t prev = order[k - 1];
    const bool breaks =
        k == order.size() ||
        traces.points[order[k]].vehicle != traces.points[prev].vehicle ||
        traces.points[order[k]].t - traces.points[prev].t > ec.max_gap_s ||
        street_of_point[order[k]] != street_of_point[prev];
    if (!breaks) continue;
    closeRun(street_of_point[prev], run_first, k - 1);
    run_first = k;
  }

  // Assemble the RoadGraph; nodes without edges are dropped (a planner must reach every node).
  std::vector<int> degree(nodes.size(), 0);
  for (const auto& s : streets) {
    ++degree[static_cast<std::size_t>(s.u)];
    ++degree[static_cast<std::size_t>(s.v)];
  }
  std::vector<int> new_id(nodes.size(), -1);
  RoadGraph& g = out.graph;
  for (std::size_t j = 0; j < nodes.size(); ++j) {
    if (degree[j] == 0) {
      ++st.isolated_nodes_dropped;
      continue;
    }
    new_id[j] = static_cast<int>(g.nodes.size());
    RoadNode rn;
    rn.id = new_id[j];
    rn.pos = nodes[j];
    g.nodes.push_back(rn);
    out.node_is_end.push_back(is_end[j]);
  }
  st.intersections = static_cast<std::size_t>(
      std::count(out.node_is_end.begin(), out.node_is_end.end(), 0));
  for (std::size_t k = 0; k < streets.size(); ++k) {
    const int u = new_id[static_cast<std::size_t>(streets[k].u)];
    const int v = new_id[static_cast<std::size_t>(streets[k].v)];
    bool f = fwd[k] >= ec.min_direction_runs, b = bwd[k] >= ec.min_direction_runs;
    if (!f && !b) {
      ++st.unknown_direction_streets;
      f = b = true;  // no usable evidence: assume two-way
    } else if (f != b) {
      ++st.one_way_streets;
    }
    auto add = [&](int from, int to, Polyline pl) {
      RoadEdge e;
      e.id = static_cast<int>(g.edges.size());
      e.u = from;
      e.v = to;
      e.length_m = polylineLength(pl);
      e.polyline = std::move(pl);
      e.street = static_cast<int>(k);
      g.edges.push_back(std::move(e));
    };
    if (f) add(u, v, polys[k]);
    if (b) add(v, u, Polyline(polys[k].rbegin(), polys[k].rend()));
  }
  if (st.unknown_direction_streets > 0)
    logWarn("build-graph: " + std::to_string(st.unknown_direction_streets) +
            " street(s) without a usable run of travel; assumed two-way");
  g.validate(where);
  st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  logInfo("build-graph: " + std::to_string(st.intersections) + " intersections, " +
          std::to_string(st.dead_ends) + " dead ends, " + std::to_string(st.streets) +
          " streets (" + std::to_string(st.one_way_streets) + " one-way), " +
          std::to_string(g.edges.size()) + " directed edges");
  return out;
}

}  // namespace slamroute::roadgraph
