// Staggered T junctions: two side streets that meet a through street a few metres apart on its
// opposite sides make one crossing place (as the place-level scoring sees it: junctions joined by
// a street whose centres lie within roadgraph.sumo.place_link_max_m). The hollow cylinder sees each
// T on its own, so the graph has a node on each and the street between them; here the pair becomes
// one node at one of the two junctions (a node at their middle would be 15-18 m from both).
#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include "DividedRoads.hpp"

namespace slamroute::roadgraph::detail {
namespace {

/// Direction from node n along an edge towards each neighbouring node (one edge per neighbour).
std::map<int, Eigen::Vector2d> armsOf(const RoadGraph& g, int n, double arm_length_m) {
  std::map<int, Eigen::Vector2d> arms;
  const Eigen::Vector2d p = g.nodes[static_cast<std::size_t>(n)].pos.head<2>();
  for (const auto& e : g.edges) {
    if (e.u == e.v || (e.u != n && e.v != n)) continue;
    const int other = e.u == n ? e.v : e.u;
    if (arms.count(other)) continue;
    const double reach = std::min(arm_length_m, 0.5 * e.length_m);
    const Eigen::Vector2d d = pointAlong(e.polyline, reach, e.v == n) - p;
    if (d.norm() > 1e-6) arms[other] = d.normalized();
  }
  return arms;
}

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

/// What a node with three arms is to the street `link` (unit, from the node towards its
/// partner) joining it to its partner.
enum class Role {
  kNone,         ///< not a T on that street
  kThroughLeft,  ///< the street runs straight on through the node; the third arm leaves left
  kThroughRight,
  kStem,  ///< the street is the T's side arm: the other two run straight on, across it
};

Role roleOf(const std::map<int, Eigen::Vector2d>& arms, int partner, const Eigen::Vector2d& link,
            double straight_deg) {
  if (arms.size() != 3 || !arms.count(partner)) return Role::kNone;
  const double straight = std::cos(straight_deg * M_PI / 180.0);
  std::vector<Eigen::Vector2d> others;
  for (const auto& [other, dir] : arms)
    if (other != partner) others.push_back(dir);
  const Eigen::Vector2d &a = others[0], &b = others[1];
  const double off_line = std::sin(straight_deg * M_PI / 180.0);
  if (a.dot(b) <= -straight && std::abs(cross(link, a)) >= straight &&
      std::abs(cross(link, b)) >= straight)
    return Role::kStem;
  for (const auto& [on, side] : {std::pair{a, b}, {b, a}})
    if (-on.dot(link) >= straight && std::abs(cross(link, side)) >= off_line)
      return cross(link, side) > 0 ? Role::kThroughLeft : Role::kThroughRight;
  return Role::kNone;
}

/// A staggered pair: both T junctions on the street joining them with their side arms on
/// opposite sides of it, or (with `jogs`) one T on it and the other T's side arm (the street
/// jogs across a crossing street). Two Ts on one side, or two stems (a short street between two
/// parallel streets), are two places. `q_role` is seen along the link from q back to p, so
/// opposite sides are the same role.
bool staggered(Role p_role, Role q_role, bool jogs) {
  const auto through = [](Role r) { return r == Role::kThroughLeft || r == Role::kThroughRight; };
  if (through(p_role) && through(q_role)) return p_role == q_role;
  return jogs &&
         ((through(p_role) && q_role == Role::kStem) || (p_role == Role::kStem && through(q_role)));
}

struct Candidate {
  double gap_m;
  int p, q;
};

/// Linked node pairs that are staggered T junctions, closest first.
std::vector<Candidate> candidates(const GraphBuildResult& out, const DividedRoadConfig& cfg,
                                  double half_height_m) {
  const RoadGraph& g = out.graph;
  const std::vector<char> mergeable = mergeableNodes(out);
  std::vector<Candidate> found;
  for (const auto& e : g.edges) {
    const int p = std::min(e.u, e.v), q = std::max(e.u, e.v);
    if (p == q || !mergeable[static_cast<std::size_t>(p)] ||
        !mergeable[static_cast<std::size_t>(q)])
      continue;
    const Point3 d =
        g.nodes[static_cast<std::size_t>(q)].pos - g.nodes[static_cast<std::size_t>(p)].pos;
    const double gap = d.head<2>().norm();
    if (gap > cfg.stagger_max_gap_m || gap < 1e-6 || std::abs(d.z()) > half_height_m) continue;
    const Eigen::Vector2d link = d.head<2>() / gap;
    const Role rp = roleOf(armsOf(g, p, cfg.arm_length_m), q, link, cfg.stagger_straight_deg);
    const Role rq = roleOf(armsOf(g, q, cfg.arm_length_m), p, -link, cfg.stagger_straight_deg);
    if (staggered(rp, rq, cfg.stagger_jogs)) found.push_back({gap, p, q});
  }
  std::sort(found.begin(), found.end(), [](const Candidate& a, const Candidate& b) {
    return a.gap_m != b.gap_m ? a.gap_m < b.gap_m : std::pair(a.p, a.q) < std::pair(b.p, b.q);
  });
  return found;
}

std::size_t edgesAt(const RoadGraph& g, int n) {
  return static_cast<std::size_t>(std::count_if(
      g.edges.begin(), g.edges.end(), [n](const RoadEdge& e) { return e.u == n || e.v == n; }));
}

}  // namespace

UnionFind staggeredPairs(const GraphBuildResult& out, const DividedRoadConfig& cfg,
                         double half_height_m, std::size_t& pairs, std::vector<double>& weight) {
  const RoadGraph& g = out.graph;
  UnionFind sets(g.nodes.size());
  weight.assign(g.nodes.size(), 1.0);
  pairs = 0;
  if (cfg.stagger_max_gap_m <= 0.0) return sets;
  std::vector<char> taken(g.nodes.size(), 0);
  for (const Candidate& c : candidates(out, cfg, half_height_m)) {
    if (taken[static_cast<std::size_t>(c.p)] || taken[static_cast<std::size_t>(c.q)]) continue;
    taken[static_cast<std::size_t>(c.p)] = taken[static_cast<std::size_t>(c.q)] = 1;
    sets.unite(c.p, c.q);
    // The node with more edges (the busier junction) keeps its position.
    const int moved = edgesAt(g, c.q) > edgesAt(g, c.p) ? c.p : c.q;
    weight[static_cast<std::size_t>(moved)] = 0.0;
    ++pairs;
  }
  return sets;
}

}  // namespace slamroute::roadgraph::detail
