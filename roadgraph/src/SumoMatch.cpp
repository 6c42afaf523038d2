// Validation of a road graph against a SUMO net (the mapping onto SUMO edges: SumoEdgeMapping.cpp).
//
// True intersections: junctions with >= 3 distinct neighbouring junctions over passenger edges
// (in or out); SUMO's "priority"/"traffic_light" types are not used
// because SUMO also splits plain streets with degree-2 junctions (shape changes, lane changes).
// A real road chain runs from one true intersection through degree-2 junctions to the next one.
#include "slamroute/roadgraph/SumoMatch.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>

#include "PointGrid.hpp"
#include "slamroute/core/DriveGraph.hpp"

namespace slamroute::roadgraph {
namespace {

/// Vertices with positions and the undirected links between them: the net's junctions over its
/// passenger edges, or the graph's nodes over its edges.
struct LinkedVertices {
  std::vector<std::string> id;
  std::vector<Point3> pos;
  std::vector<std::set<std::size_t>> nb;
  std::vector<std::pair<std::size_t, std::size_t>> links;
  void link(std::size_t u, std::size_t v) {
    if (u == v) return;
    nb[u].insert(v);
    nb[v].insert(u);
    links.emplace_back(u, v);
  }
};

LinkedVertices junctionGraph(const SumoNet& net) {
  const DriveGraph dg = DriveGraph::fromNet(net);
  LinkedVertices jg;
  const std::size_t n = dg.numVertices();
  jg.nb.resize(n);
  for (std::size_t v = 0; v < n; ++v) {
    jg.id.push_back(dg.g[v].junction_id);
    jg.pos.push_back(dg.g[v].pos);
  }
  for (const auto& e : dg.edges) jg.link(e.u, e.v);
  return jg;
}

LinkedVertices nodeGraph(const RoadGraph& graph) {
  LinkedVertices ng;
  ng.nb.resize(graph.nodes.size());
  for (const auto& n : graph.nodes) {
    ng.id.push_back(std::to_string(n.id));
    ng.pos.push_back(n.pos);
  }
  for (const auto& e : graph.edges)
    ng.link(static_cast<std::size_t>(e.u), static_cast<std::size_t>(e.v));
  return ng;
}

/// Vertices grouped into places and the graph contracted onto them: what a graph is scored
/// against (the net's junctions) and what is scored (the graph's nodes).
struct PlaceGraph {
  std::vector<std::size_t> place_of;              ///< per vertex
  std::vector<std::string> id;                    ///< per place, its vertices' ids joined by '+'
  std::vector<std::vector<std::size_t>> members;  ///< per place, its vertices
  std::vector<std::vector<Point3>> points;        ///< per place, its vertices' positions
  std::vector<std::set<std::size_t>> nb;          ///< per place, the neighbouring places
};

PlaceGraph contract(const LinkedVertices& lv, UnionFind& sets) {
  const std::size_t n = lv.nb.size();
  PlaceGraph pg;
  pg.place_of.assign(n, 0);
  std::vector<long> place_of_root(n, -1);
  for (std::size_t v = 0; v < n; ++v) {
    const auto root = static_cast<std::size_t>(sets.find(static_cast<int>(v)));
    if (place_of_root[root] < 0) {
      place_of_root[root] = static_cast<long>(pg.id.size());
      pg.id.emplace_back();
      pg.members.emplace_back();
      pg.points.emplace_back();
    }
    const auto p = static_cast<std::size_t>(place_of_root[root]);
    pg.place_of[v] = p;
    pg.id[p] += (pg.id[p].empty() ? "" : "+") + lv.id[v];
    pg.members[p].push_back(v);
    pg.points[p].push_back(lv.pos[v]);
  }
  pg.nb.resize(pg.id.size());
  for (const auto& [u, v] : lv.links) {
    const std::size_t a = pg.place_of[u], b = pg.place_of[v];
    if (a == b) continue;
    pg.nb[a].insert(b);
    pg.nb[b].insert(a);
  }
  return pg;
}

/// Each vertex a place of its own (junction level).
PlaceGraph singlePlaces(const LinkedVertices& lv) {
  UnionFind sets(lv.nb.size());
  return contract(lv, sets);
}

/// The vertex reached from v by leaving through its neighbour w and passing on through vertices
/// with exactly 2 neighbours (a street's junctions that are no intersections).
std::size_t chainEnd(const std::vector<std::set<std::size_t>>& nb, std::size_t v, std::size_t w) {
  std::size_t prev = v, cur = w;
  for (std::size_t steps = 0; nb[cur].size() == 2 && steps < nb.size(); ++steps) {
    const std::size_t a = *nb[cur].begin(), b = *nb[cur].rbegin();
    const std::size_t next = a == prev ? b : a;
    prev = cur;
    cur = next;
  }
  return cur;
}

/// Places, one rule for the net and the graph: two intersections (>= 3 distinct neighbours)
/// joined by a street (a link, or a chain of links through vertices with 2 neighbours, as SUMO
/// splits a street where its shape or lanes change) whose ends lie at most link_max_m apart are
/// one place (the carriageway crossings of a divided road, the corners of a junction box, a
/// staggered pair of T junctions). The distance is taken between the two intersections because
/// that is what both sides have: a SUMO edge's length runs between the junctions' shapes, a
/// graph edge's from node to node. `groupable` false keeps a vertex a place of its own.
PlaceGraph groupPlaces(const LinkedVertices& lv, double link_max_m,
                       const std::vector<char>& groupable) {
  UnionFind sets(lv.nb.size());
  const auto joins = [&](std::size_t v) { return groupable[v] && lv.nb[v].size() >= 3; };
  for (std::size_t v = 0; v < lv.nb.size(); ++v) {
    if (!joins(v)) continue;
    for (std::size_t w : lv.nb[v]) {
      const std::size_t end = chainEnd(lv.nb, v, w);
      if (end != v && joins(end) && (lv.pos[v] - lv.pos[end]).norm() <= link_max_m)
        sets.unite(static_cast<int>(v), static_cast<int>(end));
    }
  }
  return contract(lv, sets);
}

double placeDistance(const PlaceGraph& a, std::size_t pa, const PlaceGraph& b, std::size_t pb) {
  double d = std::numeric_limits<double>::infinity();
  for (const auto& p : a.points[pa])
    for (const auto& q : b.points[pb]) d = std::min(d, (p - q).norm());
  return d;
}

/// One-to-one matching of the detected places with the true intersections, closest pairs first;
/// a detected place lies as far from a true one as their closest two vertices.
struct PlaceMatch {
  std::vector<long> det_to_true;  ///< per detected place, truth place or -1
  std::vector<long> true_to_det;  ///< per truth place, detected place or -1
};

PlaceMatch matchPlaces(const PlaceGraph& det, const std::vector<std::size_t>& detected,
                       const PlaceGraph& t, const std::vector<std::size_t>& truth,
                       double radius_m) {
  struct Pair {
    double d;
    std::size_t det, tru;
  };
  std::vector<Pair> pairs;
  for (std::size_t d : detected)
    for (std::size_t v : truth) {
      const double dist = placeDistance(det, d, t, v);
      if (dist <= radius_m) pairs.push_back({dist, d, v});
    }
  std::sort(pairs.begin(), pairs.end(), [](const Pair& a, const Pair& b) {
    return a.d != b.d ? a.d < b.d : (a.det != b.det ? a.det < b.det : a.tru < b.tru);
  });
  PlaceMatch m;
  m.det_to_true.assign(det.id.size(), -1);
  m.true_to_det.assign(t.id.size(), -1);
  for (const auto& p : pairs) {
    if (m.det_to_true[p.det] >= 0 || m.true_to_det[p.tru] >= 0) continue;
    m.det_to_true[p.det] = static_cast<long>(p.tru);
    m.true_to_det[p.tru] = static_cast<long>(p.det);
  }
  return m;
}

using Chain = std::pair<std::size_t, std::size_t>;

/// Real chains between true intersections through places with exactly 2 neighbours.
std::set<Chain> trueChains(const PlaceGraph& t, const std::vector<std::size_t>& truth) {
  std::set<Chain> chains;
  for (std::size_t v : truth)
    for (std::size_t w : t.nb[v]) {
      const std::size_t cur = chainEnd(t.nb, v, w);
      if (t.nb[cur].size() >= 3 && cur != v) chains.insert({std::min(v, cur), std::max(v, cur)});
    }
  return chains;
}

void scoreNodes(const PlaceMatch& m, const PlaceGraph& det,
                const std::vector<std::size_t>& detected, const PlaceGraph& t,
                const std::vector<std::size_t>& truth, ValidationResult& r) {
  for (std::size_t d : detected) r.matched_nodes += m.det_to_true[d] >= 0 ? 1 : 0;
  r.true_intersections = truth.size();
  r.detected_nodes = detected.size();
  r.node_precision = detected.empty() ? 0.0 : double(r.matched_nodes) / double(detected.size());
  r.node_recall = truth.empty() ? 0.0 : double(r.matched_nodes) / double(truth.size());
  r.node_f1 = r.node_precision + r.node_recall > 0
                  ? 2 * r.node_precision * r.node_recall / (r.node_precision + r.node_recall)
                  : 0.0;
  for (std::size_t v : truth)
    if (m.true_to_det[v] < 0) r.missed_junctions.push_back(t.id[v]);
  for (std::size_t d : detected)
    if (m.det_to_true[d] < 0)
      for (std::size_t n : det.members[d]) r.false_nodes.push_back(static_cast<int>(n));
}

/// An undirected street (counted once per `street`) between two detected places matches when
/// the places are matched to the two ends of a real chain; a street inside one place is not
/// counted, as the net's edges inside a place are no chain.
void scoreStreets(const RoadGraph& graph, const std::vector<char>& node_is_end,
                  const PlaceGraph& det, const PlaceMatch& m, const std::set<Chain>& chains,
                  ValidationResult& r) {
  r.true_chains = chains.size();
  std::set<int> seen_street;
  std::set<Chain> found;
  for (const auto& e : graph.edges) {
    if (e.street >= 0 && !seen_street.insert(e.street).second) continue;
    const auto u = static_cast<std::size_t>(e.u), v = static_cast<std::size_t>(e.v);
    if (node_is_end[u] || node_is_end[v] || det.place_of[u] == det.place_of[v]) continue;
    ++r.detected_streets;
    const long a = m.det_to_true[det.place_of[u]], b = m.det_to_true[det.place_of[v]];
    if (a < 0 || b < 0) continue;
    const Chain key{std::min<std::size_t>(a, b), std::max<std::size_t>(a, b)};
    if (chains.count(key)) {
      ++r.matched_streets;
      found.insert(key);
    }
  }
  r.found_chains = found.size();
  r.edge_precision =
      r.detected_streets ? double(r.matched_streets) / double(r.detected_streets) : 0.0;
  r.edge_recall = r.true_chains ? double(r.found_chains) / double(r.true_chains) : 0.0;
}

/// Places with at least `min_neighbours` neighbouring places and, when `excluded` is given, no
/// excluded vertex among their members.
std::vector<std::size_t> placesToScore(const PlaceGraph& pg, std::size_t min_neighbours,
                                       const std::vector<char>& excluded = {}) {
  std::vector<std::size_t> out;
  for (std::size_t p = 0; p < pg.id.size(); ++p) {
    const bool skip = std::any_of(pg.members[p].begin(), pg.members[p].end(), [&](std::size_t v) {
      return v < excluded.size() && excluded[v];
    });
    if (!skip && pg.nb[p].size() >= min_neighbours) out.push_back(p);
  }
  return out;
}

/// Scores the graph's places (node_is_end: dead ends, never scored) against the net's.
ValidationResult validateAgainst(const PlaceGraph& t, const PlaceGraph& det, const RoadGraph& graph,
                                 const std::vector<char>& node_is_end, const SumoMatchConfig& cfg) {
  const std::vector<std::size_t> truth = placesToScore(t, 3);
  const std::vector<std::size_t> detected = placesToScore(det, 0, node_is_end);
  const PlaceMatch m = matchPlaces(det, detected, t, truth, cfg.match_radius_m);
  ValidationResult r;
  r.node_junction.assign(graph.nodes.size(), "");
  for (std::size_t n = 0; n < graph.nodes.size(); ++n)
    if (const long v = m.det_to_true[det.place_of[n]]; v >= 0)
      r.node_junction[n] = t.id[static_cast<std::size_t>(v)];
  scoreNodes(m, det, detected, t, truth, r);
  scoreStreets(graph, node_is_end, det, m, trueChains(t, truth), r);
  return r;
}

/// node_is_end as given, or all false when it is empty (a graph without dead-end marks).
std::vector<char> endMarks(const RoadGraph& graph, const std::vector<char>& node_is_end) {
  std::vector<char> ends(graph.nodes.size(), 0);
  for (std::size_t n = 0; n < std::min(ends.size(), node_is_end.size()); ++n)
    ends[n] = node_is_end[n];
  return ends;
}

}  // namespace

std::vector<TrueIntersection> trueIntersections(const SumoNet& net) {
  const LinkedVertices jg = junctionGraph(net);
  std::vector<TrueIntersection> out;
  for (std::size_t v = 0; v < jg.nb.size(); ++v)
    if (jg.nb[v].size() >= 3) out.push_back({jg.id[v], jg.pos[v]});
  return out;
}

std::string ValidationResult::toJson() const {
  nlohmann::json j = {{"true_intersections", true_intersections},
                      {"detected_nodes", detected_nodes},
                      {"matched_nodes", matched_nodes},
                      {"node_precision", node_precision},
                      {"node_recall", node_recall},
                      {"node_f1", node_f1},
                      {"true_chains", true_chains},
                      {"detected_streets", detected_streets},
                      {"matched_streets", matched_streets},
                      {"found_chains", found_chains},
                      {"edge_precision", edge_precision},
                      {"edge_recall", edge_recall},
                      {"missed_junctions", missed_junctions},
                      {"false_nodes", false_nodes}};
  return j.dump();
}

ValidationResult validateAgainstNet(const RoadGraph& graph, const std::vector<char>& node_is_end,
                                    const SumoNet& net, const SumoMatchConfig& cfg) {
  return validateAgainst(singlePlaces(junctionGraph(net)), singlePlaces(nodeGraph(graph)), graph,
                         endMarks(graph, node_is_end), cfg);
}

ValidationResult validateAgainstPlaces(const RoadGraph& graph, const std::vector<char>& node_is_end,
                                       const SumoNet& net, const SumoMatchConfig& cfg) {
  const LinkedVertices jg = junctionGraph(net);
  const std::vector<char> ends = endMarks(graph, node_is_end);
  std::vector<char> not_end(ends.size());
  for (std::size_t n = 0; n < ends.size(); ++n) not_end[n] = !ends[n];
  return validateAgainst(groupPlaces(jg, cfg.place_link_max_m, std::vector<char>(jg.id.size(), 1)),
                         groupPlaces(nodeGraph(graph), cfg.place_link_max_m, not_end), graph, ends,
                         cfg);
}

}  // namespace slamroute::roadgraph
