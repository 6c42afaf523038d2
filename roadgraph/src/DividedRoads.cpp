// Divided roads: two one-way carriageways side by side are one street with two directions, and
// the junctions where a street crosses them (or two divided roads cross) are one place.
//
// The hollow cylinder sees the two carriageways of a divided road as separate branches when they
// are farther apart than carriageway_gap_m, so a street crossing a divided road 10-25 m wide gets
// a node on each carriageway and a junction of two divided roads one at each corner of its box.
// Here, on the built graph:
// 1. Carriageway partners: intersection nodes p and q (at most max_node_gap_m apart, not on a
//    roundabout's ring, whose junctions stay apart) where a one-way edge leaves p and another
//    one-way edge arrives at q running side by side with it in the opposite direction: the
//    arms' directions within parallel_angle_deg, q beside p's arm (offset across it >=
//    min_offset_m, along it <= max_along_m) and the arms' far points (at arm_length_m) no
//    farther apart than max_node_gap_m; and an edge of the graph joins p and q (vehicles cross
//    the median there: two T junctions on opposite sides of a divided road that no vehicle
//    drives between are two places).
// 2. Partners are merged (transitively: the four corners of a junction box become one node) at
//    the mean of their positions; edges between nodes of one place are dropped and the polylines
//    of the others start / end at the merged node.
// 3. Staggered T junctions (StaggeredJunctions.cpp): two T junctions a street's length apart
//    whose side streets leave on opposite sides of the through street are one place too; the
//    merged node keeps one junction's position.
// 4. A one-way edge u -> v and a one-way edge v -> u of similar length are the two carriageways
//    of one street: they share one street id.
#include "DividedRoads.hpp"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "PointGrid.hpp"

namespace slamroute::roadgraph::detail {
namespace {

/// Where a one-way edge leaves (out) or enters (in) a node, seen from the node.
struct Arm {
  int edge = -1;
  bool out = false;
  Eigen::Vector2d dir = Eigen::Vector2d::Zero();  ///< from the node towards `tip`, unit
  Eigen::Vector2d tip = Eigen::Vector2d::Zero();  ///< point arm_length_m along the edge
};

std::vector<int> edgesPerStreet(const RoadGraph& g) {
  int streets = 0;
  for (const auto& e : g.edges) streets = std::max(streets, e.street + 1);
  std::vector<int> count(static_cast<std::size_t>(streets), 0);
  for (const auto& e : g.edges)
    if (e.street >= 0) ++count[static_cast<std::size_t>(e.street)];
  return count;
}

bool isOneWay(const RoadEdge& e, const std::vector<int>& per_street) {
  return e.street < 0 || per_street[static_cast<std::size_t>(e.street)] == 1;
}

/// The arms of the one-way edges at each node.
std::vector<std::vector<Arm>> oneWayArms(const RoadGraph& g, const DividedRoadConfig& cfg) {
  const std::vector<int> per_street = edgesPerStreet(g);
  std::vector<std::vector<Arm>> arms(g.nodes.size());
  for (const auto& e : g.edges) {
    if (!isOneWay(e, per_street) || e.u == e.v || e.polyline.size() < 2) continue;
    const double reach = std::min(cfg.arm_length_m, 0.5 * e.length_m);
    for (const bool out : {true, false}) {
      const int node = out ? e.u : e.v;
      Arm a;
      a.edge = e.id;
      a.out = out;
      a.tip = pointAlong(e.polyline, reach, !out);
      const Eigen::Vector2d d = a.tip - g.nodes[static_cast<std::size_t>(node)].pos.head<2>();
      if (d.norm() < 1e-6) continue;
      a.dir = d.normalized();
      arms[static_cast<std::size_t>(node)].push_back(a);
    }
  }
  return arms;
}

/// Step 1 for one pair of arms: a at node position p, b at q.
bool sideBySide(const Arm& a, const Eigen::Vector2d& p, const Arm& b, const Eigen::Vector2d& q,
                const DividedRoadConfig& cfg) {
  if (a.out == b.out || a.edge == b.edge) return false;
  if (a.dir.dot(b.dir) < std::cos(cfg.parallel_angle_deg * M_PI / 180.0)) return false;
  const Eigen::Vector2d d = q - p;
  const double across = std::abs(a.dir.x() * d.y() - a.dir.y() * d.x());
  const double along = std::abs(a.dir.dot(d));
  return across >= cfg.min_offset_m && along <= cfg.max_along_m &&
         (a.tip - b.tip).norm() <= cfg.max_node_gap_m;
}

/// Step 1: the carriageway partners, as sets of nodes (root = smallest id).
UnionFind carriagewayPartners(const GraphBuildResult& out, const DividedRoadConfig& cfg,
                              double half_height_m, std::size_t& pairs) {
  const RoadGraph& g = out.graph;
  const auto arms = oneWayArms(g, cfg);
  const std::vector<char> mergeable = mergeableNodes(out);
  std::set<std::pair<int, int>> linked;  // nodes joined by an edge (the crossing street)
  for (const auto& e : g.edges) linked.insert({std::min(e.u, e.v), std::max(e.u, e.v)});
  UnionFind sets(g.nodes.size());
  for (std::size_t p = 0; p < g.nodes.size(); ++p)
    for (std::size_t q = p + 1; q < g.nodes.size(); ++q) {
      if (!mergeable[p] || !mergeable[q]) continue;
      if (!linked.count({static_cast<int>(p), static_cast<int>(q)})) continue;
      const Point3 &pp = g.nodes[p].pos, &pq = g.nodes[q].pos;
      if ((pp - pq).head<2>().norm() > cfg.max_node_gap_m ||
          std::abs(pp.z() - pq.z()) > half_height_m)
        continue;
      bool partners = false;
      for (const Arm& a : arms[p])
        for (const Arm& b : arms[q])
          partners = partners || sideBySide(a, pp.head<2>(), b, pq.head<2>(), cfg);
      if (!partners) continue;
      sets.unite(static_cast<int>(p), static_cast<int>(q));
      ++pairs;
    }
  return sets;
}

/// Moves the polyline's end at an old node position to the merged node's position.
void moveEnd(Polyline& pl, bool front, const Point3& old_pos, const Point3& new_pos) {
  if (old_pos == new_pos) return;
  Point3& end = front ? pl.front() : pl.back();
  if ((end - old_pos).norm() <= 0.5)
    end = new_pos;
  else if (front)
    pl.insert(pl.begin(), new_pos);
  else
    pl.push_back(new_pos);
}

/// Step 2: one node per set at the weighted mean of its members, the edges between sets.
void contractPlaces(GraphBuildResult& out, UnionFind& sets, const std::vector<double>& weight) {
  RoadGraph& g = out.graph;
  const std::size_t n = g.nodes.size();
  std::vector<int> new_id(n, -1);
  std::vector<Point3> sum;
  std::vector<double> members;
  std::vector<char> is_end;
  for (std::size_t v = 0; v < n; ++v) {
    const auto root = static_cast<std::size_t>(sets.find(static_cast<int>(v)));
    if (new_id[root] < 0) {
      new_id[root] = static_cast<int>(sum.size());
      sum.push_back(Point3::Zero());
      members.push_back(0.0);
      is_end.push_back(out.node_is_end[v]);
    }
    new_id[v] = new_id[root];
    sum[static_cast<std::size_t>(new_id[v])] += weight[v] * g.nodes[v].pos;
    members[static_cast<std::size_t>(new_id[v])] += weight[v];
  }
  std::vector<RoadNode> nodes(sum.size());
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    nodes[k].id = static_cast<int>(k);
    nodes[k].pos = sum[k] / members[k];
  }
  std::vector<RoadEdge> edges;
  for (auto& e : g.edges) {
    const int u = new_id[static_cast<std::size_t>(e.u)], v = new_id[static_cast<std::size_t>(e.v)];
    if (u == v && e.u != e.v) continue;  // inside one place
    moveEnd(e.polyline, true, g.nodes[static_cast<std::size_t>(e.u)].pos,
            nodes[static_cast<std::size_t>(u)].pos);
    moveEnd(e.polyline, false, g.nodes[static_cast<std::size_t>(e.v)].pos,
            nodes[static_cast<std::size_t>(v)].pos);
    e.u = u;
    e.v = v;
    e.length_m = polylineLength(e.polyline);
    e.id = static_cast<int>(edges.size());
    edges.push_back(std::move(e));
  }
  g.nodes = std::move(nodes);
  g.edges = std::move(edges);
  out.node_is_end = std::move(is_end);
}

/// A place whose every edge ran inside it has none left: a planner must reach every node, so it
/// goes (as assembleGraph drops nodes without streets).
void dropNodesWithoutEdges(GraphBuildResult& out) {
  RoadGraph& g = out.graph;
  std::vector<int> new_id(g.nodes.size(), -1);
  for (const auto& e : g.edges)
    new_id[static_cast<std::size_t>(e.u)] = new_id[static_cast<std::size_t>(e.v)] = 0;
  if (std::count(new_id.begin(), new_id.end(), -1) == 0) return;
  std::vector<RoadNode> nodes;
  std::vector<char> is_end;
  for (std::size_t n = 0; n < g.nodes.size(); ++n) {
    if (new_id[n] < 0) continue;
    new_id[n] = static_cast<int>(nodes.size());
    nodes.push_back(g.nodes[n]);
    nodes.back().id = new_id[n];
    is_end.push_back(out.node_is_end[n]);
  }
  for (auto& e : g.edges) {
    e.u = new_id[static_cast<std::size_t>(e.u)];
    e.v = new_id[static_cast<std::size_t>(e.v)];
  }
  out.stats.isolated_nodes_dropped += g.nodes.size() - nodes.size();
  g.nodes = std::move(nodes);
  out.node_is_end = std::move(is_end);
}

/// Step 3: one street id for the two carriageways (one-way u -> v and v -> u, similar length).
std::size_t pairCarriageways(RoadGraph& g, const DividedRoadConfig& cfg) {
  const std::vector<int> per_street = edgesPerStreet(g);
  std::map<std::pair<int, int>, std::vector<int>> one_way;  // (u, v) -> edges
  for (const auto& e : g.edges)
    if (e.street >= 0 && isOneWay(e, per_street)) one_way[{e.u, e.v}].push_back(e.id);
  std::vector<char> paired(g.edges.size(), 0);
  std::size_t pairs = 0;
  for (auto& e : g.edges) {
    if (paired[static_cast<std::size_t>(e.id)] || e.u == e.v) continue;
    const auto it = one_way.find({e.v, e.u});
    if (it == one_way.end() || one_way.count({e.u, e.v}) == 0) continue;
    for (const int f_id : it->second) {
      RoadEdge& f = g.edges[static_cast<std::size_t>(f_id)];
      const double longer = std::max(e.length_m, f.length_m);
      if (paired[static_cast<std::size_t>(f_id)] ||
          std::abs(e.length_m - f.length_m) > std::max(cfg.max_node_gap_m, 0.3 * longer))
        continue;
      f.street = e.street;
      paired[static_cast<std::size_t>(f_id)] = paired[static_cast<std::size_t>(e.id)] = 1;
      ++pairs;
      break;
    }
  }
  return pairs;
}

void recount(const RoadGraph& g, const std::vector<char>& node_is_end, GraphBuildStats& st) {
  st.intersections =
      static_cast<std::size_t>(std::count(node_is_end.begin(), node_is_end.end(), 0));
  st.dead_ends =
      static_cast<std::size_t>(std::count(node_is_end.begin(), node_is_end.end(), kDeadEnd));
  const std::vector<int> per_street = edgesPerStreet(g);
  st.streets = st.one_way_streets = 0;
  for (const int k : per_street) {
    st.streets += k > 0 ? 1 : 0;
    st.one_way_streets += k == 1 ? 1 : 0;
  }
}

}  // namespace

/// The point `s` metres along pl from its start (from its end when from_end).
Eigen::Vector2d pointAlong(const Polyline& pl, double s, bool from_end) {
  const std::size_t n = pl.size();
  for (std::size_t k = 0; k + 1 < n; ++k) {
    const Point3& a = from_end ? pl[n - 1 - k] : pl[k];
    const Point3& b = from_end ? pl[n - 2 - k] : pl[k + 1];
    const double len = (b - a).head<2>().norm();
    if (s <= len && len > 0.0) return (a + (b - a) * (s / len)).head<2>();
    s -= len;
  }
  return (from_end ? pl.front() : pl.back()).head<2>();
}

std::vector<char> mergeableNodes(const GraphBuildResult& out) {
  std::vector<char> ok(out.graph.nodes.size(), 0);
  for (std::size_t n = 0; n < ok.size(); ++n) {
    const Point3& p = out.graph.nodes[n].pos;
    ok[n] = !out.node_is_end[n];
    for (const auto& rb : out.roundabouts)
      for (const auto& j : rb.junctions)
        if ((j - p).norm() < 1e-6) ok[n] = 0;
  }
  return ok;
}

void mergeDividedRoads(GraphBuildResult& out, const DividedRoadConfig& cfg, double half_height_m) {
  if (!cfg.enabled) return;
  std::size_t pairs = 0;
  UnionFind sets = carriagewayPartners(out, cfg, half_height_m, pairs);
  out.stats.divided_node_pairs = pairs;
  if (pairs > 0) {
    contractPlaces(out, sets, std::vector<double>(out.graph.nodes.size(), 1.0));
    dropNodesWithoutEdges(out);
  }
  std::size_t staggered = 0;
  std::vector<double> weight;
  UnionFind stagger_sets = staggeredPairs(out, cfg, half_height_m, staggered, weight);
  out.stats.staggered_node_pairs = staggered;
  if (staggered > 0) {
    contractPlaces(out, stagger_sets, weight);
    dropNodesWithoutEdges(out);
  }
  out.stats.divided_streets = pairCarriageways(out.graph, cfg);
  if (pairs > 0 || staggered > 0 || out.stats.divided_streets > 0)
    recount(out.graph, out.node_is_end, out.stats);
}

}  // namespace slamroute::roadgraph::detail
