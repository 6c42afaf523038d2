// Validation against a SUMO net and mapping of graph edges to SUMO edges.
//
// True intersections: junctions with >= 3 distinct neighbouring junctions over passenger edges
// (in or out); SUMO's "priority"/"traffic_light" types are not used
// because SUMO also splits plain streets with degree-2 junctions (shape changes, lane changes).
// A real road chain runs from one true intersection through degree-2 junctions to the next one.
#include "slamroute/roadgraph/SumoMatch.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <unordered_map>

#include "PointGrid.hpp"
#include "slamroute/core/DriveGraph.hpp"
#include "slamroute/core/Log.hpp"

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

namespace {

/// The net's passenger lanes sampled every 2 m with their direction of travel, and SUMO's
/// connections between the passenger edges.
class SumoLanes {
 public:
  SumoLanes(const SumoNet& net, double cell_m) : net_(net) {
    for (const auto& e : net.edges) {
      if (e.isInternal() || !e.allowsPassenger()) continue;
      const int id = static_cast<int>(edges_.size());
      edges_.push_back(&e);
      out_of_[e.from].push_back(&e);
      for (const auto& lane : e.lanes)
        if (lane.allowsPassenger()) sampleLane(lane, id);
    }
    grid_.emplace(samples_, cell_m);
  }
  const SumoEdge& edge(int k) const { return *edges_[static_cast<std::size_t>(k)]; }
  bool turnAllowed(int a, int b) const { return net_.turnAllowed(edge(a).id, edge(b).id); }

  /// The passenger edge of the nearest lane sample within max_dist of p whose direction is
  /// within ~70 degrees of t; -1 when there is none.
  int nearestEdge(const Point3& p, const Vec3& t, double max_dist) const {
    int best = -1;
    double bd = std::numeric_limits<double>::infinity();
    grid_->forEachNear(p, max_dist, max_dist, [&](int j) {
      const auto k = static_cast<std::size_t>(j);
      if (tangent_[k].dot(t) < 0.3) return;  // opposite direction
      const double dd = (samples_[k] - p).squaredNorm();
      if (dd < bd) {
        bd = dd;
        best = sample_edge_[k];
      }
    });
    return best;
  }

  /// Shortest connection a -> b over at most 4 intermediate edges allowed by SUMO's
  /// connections: the edges in between, {"."} when b follows a directly, {} when none.
  std::vector<std::string> bridge(int a, int b) const {
    const SumoEdge* target = edges_[static_cast<std::size_t>(b)];
    std::deque<std::pair<const SumoEdge*, std::vector<std::string>>> q;
    q.push_back({edges_[static_cast<std::size_t>(a)], {}});
    std::set<std::string> seen{edge(a).id};
    while (!q.empty()) {
      auto [cur, path] = q.front();
      q.pop_front();
      if (path.size() > 4) continue;
      const auto it = out_of_.find(cur->to);
      if (it == out_of_.end()) continue;
      for (const SumoEdge* nx : it->second) {
        if (!net_.turnAllowed(cur->id, nx->id)) continue;
        if (nx == target) return path.empty() ? std::vector<std::string>{"."} : path;
        if (!seen.insert(nx->id).second) continue;
        auto longer = path;
        longer.push_back(nx->id);
        q.push_back({nx, std::move(longer)});
      }
    }
    return {};
  }

 private:
  void sampleLane(const SumoLane& lane, int edge_id) {
    for (std::size_t k = 0; k + 1 < lane.shape.size(); ++k) {
      const Vec3 d = lane.shape[k + 1] - lane.shape[k];
      const double len = d.norm();
      if (len < 1e-6) continue;
      const int m = std::max(1, static_cast<int>(std::ceil(len / 2.0)));
      for (int q = 0; q <= m; ++q) {
        samples_.push_back(lane.shape[k] + d * (static_cast<double>(q) / m));
        tangent_.push_back(d / len);
        sample_edge_.push_back(edge_id);
      }
    }
  }

  const SumoNet& net_;
  std::vector<Point3> samples_;
  std::vector<Vec3> tangent_;
  std::vector<int> sample_edge_;
  std::vector<const SumoEdge*> edges_;
  std::unordered_map<std::string, std::vector<const SumoEdge*>> out_of_;  // junction -> edges
  std::optional<detail::PointGrid> grid_;
};

/// SUMO edges along a polyline in order, each with the number of samples that matched it.
struct EdgeRun {
  std::vector<int> edge, samples;
};

/// Samples the polyline every sample_step_m (skipping end_skip_m at both ends, except the
/// middle sample) and matches each sample to the nearest lane in its direction.
EdgeRun sumoEdgesAlong(const Polyline& pl, const SumoLanes& lanes, const SumoMatchConfig& cfg) {
  EdgeRun run;
  const double total = polylineLength(pl);
  double s = 0.0;
  for (std::size_t k = 0; k + 1 < pl.size(); ++k) {
    const Vec3 d = pl[k + 1] - pl[k];
    const double len = d.norm();
    if (len < 1e-6) continue;
    const Vec3 t = d / len;
    for (double a = 0.0; a < len; a += cfg.sample_step_m) {
      const double pos = s + a;
      const bool interior = pos >= cfg.end_skip_m && pos <= total - cfg.end_skip_m;
      const bool middle = std::abs(pos - 0.5 * total) < 0.5 * cfg.sample_step_m;
      if (!interior && !middle) continue;
      const int best = lanes.nearestEdge(pl[k] + t * a, t, cfg.max_lane_dist_m);
      if (best < 0) continue;
      if (run.edge.empty() || run.edge.back() != best) {
        run.edge.push_back(best);
        run.samples.push_back(0);
      }
      ++run.samples.back();
    }
    s += len;
  }
  return run;
}

/// Drops A-B-A flickers (a sample snapping to a neighbouring edge for one step).
void dropFlickers(EdgeRun& run) {
  auto& seq = run.edge;
  auto& cnt = run.samples;
  for (std::size_t k = 1; k + 1 < seq.size();) {
    if (seq[k - 1] == seq[k + 1]) {
      cnt[k - 1] += cnt[k + 1];
      seq.erase(seq.begin() + static_cast<long>(k), seq.begin() + static_cast<long>(k) + 2);
      cnt.erase(cnt.begin() + static_cast<long>(k), cnt.begin() + static_cast<long>(k) + 2);
      k = std::max<std::size_t>(1, k - 1);
    } else {
      ++k;
    }
  }
}

/// Keeps the drivable chain with the most samples (longest path in the DAG of the sequence
/// whose links are allowed turns or bridgeable within 4 edges): samples snapping to the other
/// carriageway or a crossing street for a few steps cannot be driven and are dropped. Returns
/// the SUMO edges of the chain; adds the matches dropped to `dropped`.
std::vector<int> drivableChain(const EdgeRun& run, const SumoLanes& lanes, std::size_t& dropped) {
  const std::vector<int>& seq = run.edge;
  if (seq.size() <= 1) return seq;
  const std::size_t m = seq.size();
  std::map<std::pair<int, int>, bool> linkable;
  auto link = [&](int a, int b) {
    if (a == b) return true;
    const auto [it, fresh] = linkable.try_emplace({a, b}, false);
    if (fresh) it->second = lanes.turnAllowed(a, b) || !lanes.bridge(a, b).empty();
    return it->second;
  };
  std::vector<int> score(m, 0), parent(m, -1);
  for (std::size_t k = 0; k < m; ++k) {
    score[k] = run.samples[k];
    for (std::size_t j = 0; j < k; ++j)
      if (score[j] + run.samples[k] > score[k] && link(seq[j], seq[k])) {
        score[k] = score[j] + run.samples[k];
        parent[k] = static_cast<int>(j);
      }
  }
  int k = static_cast<int>(std::max_element(score.begin(), score.end()) - score.begin());
  std::vector<int> chain;
  for (; k >= 0; k = parent[static_cast<std::size_t>(k)]) {
    const int e = seq[static_cast<std::size_t>(k)];
    if (chain.empty() || chain.back() != e) chain.push_back(e);
  }
  dropped += m - chain.size();
  return {chain.rbegin(), chain.rend()};
}

/// A chain should leave u and reach v. An end edge pointing the other way (a crossing road's
/// lane arriving at u, or one leaving v, matched by the samples next to the node) is stray:
/// its `near` end lies close to the node and closer than its other end.
bool strayEnd(const SumoEdge& e, const Point3& node, bool arriving, const SumoMatchConfig& cfg) {
  if (e.length() < cfg.stray_min_length_m || e.shape.empty()) return false;
  const double near = ((arriving ? e.shape.back() : e.shape.front()) - node).head<2>().norm();
  const double far = ((arriving ? e.shape.front() : e.shape.back()) - node).head<2>().norm();
  return near < std::min(cfg.stray_radius_m, far);
}

/// Drops stray end edges of the chain of graph edge ge; returns how many.
std::size_t dropStrayEnds(std::vector<int>& chain, const RoadGraph& graph, const RoadEdge& ge,
                          const SumoLanes& lanes, const SumoMatchConfig& cfg) {
  std::size_t strays = 0;
  const auto node = [&](int n) { return graph.nodes[static_cast<std::size_t>(n)].pos; };
  if (chain.size() >= 2 && strayEnd(lanes.edge(chain.front()), node(ge.u), true, cfg)) {
    chain.erase(chain.begin());
    ++strays;
  }
  if (chain.size() >= 2 && strayEnd(lanes.edge(chain.back()), node(ge.v), false, cfg)) {
    chain.pop_back();
    ++strays;
  }
  return strays;
}

/// Drops connectors (edges shorter than connector_max_m) from both ends of the chain while an
/// edge of a street is left; returns how many. A connector joins two junctions a fraction of a
/// metre apart (OSM nets split a street there), so the samples next to a node fall on it or on
/// the street past it by chance; as the first edge of a chain it makes the turn test ask for a
/// turn into it from a street that reaches only the street past it (Bologna 2 -> 203[1]b at
/// junction 3: refused, while 2 -> 202 is allowed). The turn test and the routes bridge it.
std::size_t dropConnectorEnds(std::vector<int>& chain, const SumoLanes& lanes,
                              const SumoMatchConfig& cfg) {
  std::size_t dropped = 0;
  const auto connector = [&](int k) { return lanes.edge(k).length() < cfg.connector_max_m; };
  for (; chain.size() >= 2 && connector(chain.front()); ++dropped) chain.erase(chain.begin());
  for (; chain.size() >= 2 && connector(chain.back()); ++dropped) chain.pop_back();
  return dropped;
}

/// Drops end edges of the chain that SUMO joins to their neighbour in the chain only through
/// other edges and that at most bridged_end_max_samples samples matched; returns how many. They
/// are lanes of another arm beside the node: where a junction's node lies off the point where
/// its arms meet (Bologna junction 9), the stretch from the node to the street crosses the
/// junction box past them, and the bridge to the street runs round a block.
std::size_t dropBridgedEnds(std::vector<int>& chain, const EdgeRun& run, const SumoLanes& lanes,
                            const SumoMatchConfig& cfg) {
  const auto weak = [&](int e) {
    int n = 0;
    for (std::size_t k = 0; k < run.edge.size(); ++k) n += run.edge[k] == e ? run.samples[k] : 0;
    return n <= cfg.bridged_end_max_samples;
  };
  std::size_t dropped = 0;
  for (; chain.size() >= 2 && weak(chain[0]) && !lanes.turnAllowed(chain[0], chain[1]); ++dropped)
    chain.erase(chain.begin());
  for (std::size_t n = chain.size();
       n >= 2 && weak(chain[n - 1]) && !lanes.turnAllowed(chain[n - 2], chain[n - 1]);
       n = chain.size(), ++dropped)
    chain.pop_back();
  return dropped;
}

/// The SUMO edge ids of the chain with the edges that bridge consecutive ones SUMO does not
/// connect directly; counts the pairs no bridge joins in `gaps`.
std::vector<std::string> bridgedIds(const std::vector<int>& chain, const SumoLanes& lanes,
                                    std::size_t& gaps) {
  std::vector<std::string> ids;
  for (std::size_t k = 0; k < chain.size(); ++k) {
    if (k > 0 && !lanes.turnAllowed(chain[k - 1], chain[k])) {
      const auto path = lanes.bridge(chain[k - 1], chain[k]);
      if (path.empty()) ++gaps;
      for (const auto& id : path)
        if (id != ".") ids.push_back(id);
    }
    ids.push_back(lanes.edge(chain[k]).id);
  }
  return ids;
}

}  // namespace

std::size_t mapSumoEdges(RoadGraph& graph, const SumoNet& net, const SumoMatchConfig& cfg) {
  const SumoLanes lanes(net, std::max(cfg.max_lane_dist_m, 1.0));
  std::size_t unmapped = 0, gaps = 0, dropped = 0, strays = 0, connectors = 0, bridged = 0;
  for (auto& ge : graph.edges) {
    EdgeRun run = sumoEdgesAlong(ge.polyline, lanes, cfg);
    dropFlickers(run);
    std::vector<int> chain = drivableChain(run, lanes, dropped);
    connectors += dropConnectorEnds(chain, lanes, cfg);
    bridged += dropBridgedEnds(chain, run, lanes, cfg);
    strays += dropStrayEnds(chain, graph, ge, lanes, cfg);
    ge.sumo_edges = bridgedIds(chain, lanes, gaps);
    if (ge.sumo_edges.empty()) ++unmapped;
  }
  const auto report = [](std::size_t n, const std::string& what) {
    if (n > 0) logInfo("build-graph: " + std::to_string(n) + " " + what);
  };
  report(dropped,
         "SUMO edge match(es) dropped that no drivable chain along their graph edge passes");
  report(
      strays,
      "SUMO edge(s) dropped from chain ends that arrive at the start node or leave the end node");
  report(connectors,
         "connector edge(s) (shorter than sumo.connector_max_m) dropped from chain ends");
  report(bridged,
         "weakly matched SUMO edge(s) joined to their chain only by a bridge dropped from chain "
         "ends");
  if (gaps > 0)
    logWarn("build-graph: " + std::to_string(gaps) +
            " gap(s) between consecutive SUMO edges could not be bridged");
  return unmapped;
}

}  // namespace slamroute::roadgraph
