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
#include <set>
#include <unordered_map>

#include "PointGrid.hpp"
#include "slamroute/core/DriveGraph.hpp"
#include "slamroute/core/Log.hpp"

namespace slamroute::roadgraph {
namespace {

/// Undirected neighbour sets of the drivable junction graph.
struct JunctionGraph {
  std::vector<std::string> id;
  std::vector<Point3> pos;
  std::vector<std::set<std::size_t>> nb;
};

JunctionGraph junctionGraph(const SumoNet& net) {
  const DriveGraph dg = DriveGraph::fromNet(net);
  JunctionGraph jg;
  const std::size_t n = dg.numVertices();
  jg.nb.resize(n);
  for (std::size_t v = 0; v < n; ++v) {
    jg.id.push_back(dg.g[v].junction_id);
    jg.pos.push_back(dg.g[v].pos);
  }
  for (const auto& e : dg.edges)
    if (e.u != e.v) {
      jg.nb[e.u].insert(e.v);
      jg.nb[e.v].insert(e.u);
    }
  return jg;
}

}  // namespace

std::vector<TrueIntersection> trueIntersections(const SumoNet& net) {
  const JunctionGraph jg = junctionGraph(net);
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
  const JunctionGraph jg = junctionGraph(net);
  std::vector<std::size_t> truth;
  for (std::size_t v = 0; v < jg.nb.size(); ++v)
    if (jg.nb[v].size() >= 3) truth.push_back(v);
  auto isEnd = [&](std::size_t n) { return n < node_is_end.size() && node_is_end[n]; };
  std::vector<int> detected;
  for (std::size_t n = 0; n < graph.nodes.size(); ++n)
    if (!isEnd(n)) detected.push_back(static_cast<int>(n));

  // Greedy one-to-one matching, closest pairs first.
  struct Pair {
    double d;
    int det;
    std::size_t tru;
  };
  std::vector<Pair> pairs;
  for (int d : detected)
    for (std::size_t t : truth) {
      const double dist = (graph.nodes[static_cast<std::size_t>(d)].pos - jg.pos[t]).norm();
      if (dist <= cfg.match_radius_m) pairs.push_back({dist, d, t});
    }
  std::sort(pairs.begin(), pairs.end(), [](const Pair& a, const Pair& b) {
    return a.d != b.d ? a.d < b.d : (a.det != b.det ? a.det < b.det : a.tru < b.tru);
  });
  std::vector<long> det_to_true(graph.nodes.size(), -1);
  std::vector<int> true_to_det(jg.nb.size(), -1);
  ValidationResult r;
  r.node_junction.assign(graph.nodes.size(), "");
  for (const auto& p : pairs) {
    if (det_to_true[static_cast<std::size_t>(p.det)] >= 0 || true_to_det[p.tru] >= 0) continue;
    det_to_true[static_cast<std::size_t>(p.det)] = static_cast<long>(p.tru);
    true_to_det[p.tru] = p.det;
    r.node_junction[static_cast<std::size_t>(p.det)] = jg.id[p.tru];
    ++r.matched_nodes;
  }
  r.true_intersections = truth.size();
  r.detected_nodes = detected.size();
  r.node_precision = detected.empty() ? 0.0 : double(r.matched_nodes) / double(detected.size());
  r.node_recall = truth.empty() ? 0.0 : double(r.matched_nodes) / double(truth.size());
  r.node_f1 = r.node_precision + r.node_recall > 0
                  ? 2 * r.node_precision * r.node_recall / (r.node_precision + r.node_recall)
                  : 0.0;
  for (std::size_t t : truth)
    if (true_to_det[t] < 0) r.missed_junctions.push_back(jg.id[t]);
  for (int d : detected)
    if (det_to_true[static_cast<std::size_t>(d)] < 0) r.false_nodes.push_back(d);

  // Real chains between true intersections through degree-2 junctions.
  std::set<std::pair<std::size_t, std::size_t>> chains;
  for (std::size_t v : truth)
    for (std::size_t w : jg.nb[v]) {
      std::size_t prev = v, cur = w;
      for (std::size_t steps = 0; jg.nb[cur].size() == 2 && steps < jg.nb.size(); ++steps) {
        const std::size_t a = *jg.nb[cur].begin(), b = *jg.nb[cur].rbegin();
        const std::size_t next = a == prev ? b : a;
        prev = cur;
        cur = next;
      }
      if (jg.nb[cur].size() >= 3 && cur != v) chains.insert({std::min(v, cur), std::max(v, cur)});
    }
  r.true_chains = chains.size();
  std::set<int> seen_street;
  std::set<std::pair<std::size_t, std::size_t>> found;
  for (const auto& e : graph.edges) {
    if (e.street >= 0 && !seen_street.insert(e.street).second) continue;
    if (isEnd(static_cast<std::size_t>(e.u)) || isEnd(static_cast<std::size_t>(e.v))) continue;
    ++r.detected_streets;
    const long a = det_to_true[static_cast<std::size_t>(e.u)];
    const long b = det_to_true[static_cast<std::size_t>(e.v)];
    if (a < 0 || b < 0) continue;
    const std::pair<std::size_t, std::size_t> key{std::min<std::size_t>(a, b), std::max<std::size_t>(a, b)};
    if (chains.count(key)) {
      ++r.matched_streets;
      found.insert(key);
    }
  }
  r.found_chains = found.size();
  r.edge_precision = r.detected_streets ? double(r.matched_streets) / double(r.detected_streets) : 0.0;
  r.edge_recall = r.true_chains ? double(r.found_chains) / double(r.true_chains) : 0.0;
  return r;
}

std::size_t mapSumoEdges(RoadGraph& graph, const SumoNet& net, const SumoMatchConfig& cfg) {
  // Lane samples every 2 m with their direction of travel.
  std::vector<Point3> samples;
  std::vector<Vec3> tangent;
  std::vector<int> sample_edge;
  std::vector<const SumoEdge*> edges;
  std::unordered_map<std::string, std::vector<const SumoEdge*>> out_of;  // junction -> edges
  for (const auto& e : net.edges) {
    if (e.isInternal() || !e.allowsPassenger()) continue;
    const int id = static_cast<int>(edges.size());
    edges.push_back(&e);
    out_of[e.from].push_back(&e);
    for (const auto& lane : e.lanes) {
      if (!lane.allowsPassenger()) continue;
      for (std::size_t k = 0; k + 1 < lane.shape.size(); ++k) {
        const Vec3 d = lane.shape[k + 1] - lane.shape[k];
        const double len = d.norm();
        if (len < 1e-6) continue;
        const int m = std::max(1, static_cast<int>(std::ceil(len / 2.0)));
        for (int q = 0; q <= m; ++q) {
          samples.push_back(lane.shape[k] + d * (static_cast<double>(q) / m));
          tangent.push_back(d / len);
          sample_edge.push_back(id);
        }
      }
    }
  }
  const detail::PointGrid grid(samples, std::max(cfg.max_lane_dist_m, 1.0));
  // Shortest connection a -> b over at most 4 intermediate edges allowed by SUMO's connections.
  auto bridge = [&](const SumoEdge* a, const SumoEdge* b) -> std::vector<std::string> {
    std::deque<std::pair<const SumoEdge*, std::vector<std::string>>> q;
    q.push_back({a, {}});
    std::set<std::string> seen{a->id};
    while (!q.empty()) {
      auto [cur, path] = q.front();
      q.pop_front();
      if (path.size() > 4) continue;
      const auto it = out_of.find(cur->to);
      if (it == out_of.end()) continue;
      for (const SumoEdge* nx : it->second) {
        if (!net.turnAllowed(cur->id, nx->id)) continue;
        if (nx == b) return path.empty() ? std::vector<std::string>{"."} : path;
        if (!seen.insert(nx->id).second) continue;
        auto p2 = path;
        p2.push_back(nx->id);
        q.push_back({nx, std::move(p2)});
      }
    }
    return {};
  };
  std::size_t unmapped = 0, gaps = 0, dropped = 0, strays = 0;
  for (auto& ge : graph.edges) {
    ge.sumo_edges.clear();
    const auto& pl = ge.polyline;
    const double total = polylineLength(pl);
    std::vector<int> seq, cnt;  // SUMO edges along the polyline, samples on each
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
        const Point3 p = pl[k] + t * a;
        int best = -1;
        double bd = std::numeric_limits<double>::infinity();
        grid.forEachNear(p, cfg.max_lane_dist_m, cfg.max_lane_dist_m, [&](int j) {
          if (tangent[static_cast<std::size_t>(j)].dot(t) < 0.3) return;  // opposite direction
          const double dd = (samples[static_cast<std::size_t>(j)] - p).squaredNorm();
          if (dd < bd) {
            bd = dd;
            best = sample_edge[static_cast<std::size_t>(j)];
          }
        });
        if (best >= 0 && (seq.empty() || seq.back() != best)) {
          seq.push_back(best);
          cnt.push_back(0);
        }
        if (best >= 0) ++cnt.back();
      }
      s += len;
    }
    // Drop A-B-A flickers (a sample snapping to a neighbouring edge for one step).
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
    // Keep the drivable chain with the most samples (longest path in the DAG of the sequence
    // whose links are allowed turns or bridgeable within 4 edges): samples snapping to the other
    // carriageway or a crossing street for a few steps cannot be driven and are dropped.
    if (seq.size() > 1) {
      const std::size_t m = seq.size();
      std::map<std::pair<int, int>, bool> linkable;
      auto link = [&](int a, int b) {
        if (a == b) return true;
        const auto key = std::make_pair(a, b);
        const auto it = linkable.find(key);
        if (it != linkable.end()) return it->second;
        const SumoEdge* ea = edges[static_cast<std::size_t>(a)];
        const SumoEdge* eb = edges[static_cast<std::size_t>(b)];
        const bool ok = net.turnAllowed(ea->id, eb->id) || !bridge(ea, eb).empty();
        linkable.emplace(key, ok);
        return ok;
      };
      std::vector<int> score(m, 0), parent(m, -1);
      for (std::size_t k = 0; k < m; ++k) {
        score[k] = cnt[k];
        for (std::size_t j = 0; j < k; ++j)
          if (score[j] + cnt[k] > score[k] && link(seq[j], seq[k])) {
            score[k] = score[j] + cnt[k];
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
      seq.assign(chain.rbegin(), chain.rend());
    }
    // A chain should leave u and reach v. An end edge pointing the other way (a crossing road's
    // lane arriving at u, or one leaving v, matched by the samples next to the node) is stray:
    // its `near` end lies close to the node and closer than its other end.
    auto stray = [&](int sumo, int node, bool arriving) {
      const SumoEdge* e = edges[static_cast<std::size_t>(sumo)];
      if (e->length() < cfg.stray_min_length_m || e->shape.empty()) return false;
      const Point3& p = graph.nodes[static_cast<std::size_t>(node)].pos;
      const double near = ((arriving ? e->shape.back() : e->shape.front()) - p).head<2>().norm();
      const double far = ((arriving ? e->shape.front() : e->shape.back()) - p).head<2>().norm();
      return near < std::min(cfg.stray_radius_m, far);
    };
    if (seq.size() >= 2 && stray(seq.front(), ge.u, /*arriving=*/true)) {
      seq.erase(seq.begin());
      ++strays;
    }
    if (seq.size() >= 2 && stray(seq.back(), ge.v, /*arriving=*/false)) {
      seq.pop_back();
      ++strays;
    }
    for (std::size_t k = 0; k < seq.size(); ++k) {
      const SumoEdge* cur = edges[static_cast<std::size_t>(seq[k])];
      if (k > 0) {
        const SumoEdge* prev = edges[static_cast<std::size_t>(seq[k - 1])];
        if (!net.turnAllowed(prev->id, cur->id)) {
          const auto path = bridge(prev, cur);
          if (path.empty()) ++gaps;
          for (const auto& id : path)
            if (id != ".") ge.sumo_edges.push_back(id);
        }
      }
      ge.sumo_edges.push_back(cur->id);
    }
    if (ge.sumo_edges.empty()) ++unmapped;
  }
  if (dropped > 0)
    logInfo("build-graph: " + std::to_string(dropped) +
            " SUMO edge match(es) dropped that no drivable chain along their graph edge passes");
  if (strays > 0)
    logInfo("build-graph: " + std::to_string(strays) +
            " SUMO edge(s) dropped from chain ends that arrive at the start node or leave the end node");
  if (gaps > 0)
    logWarn("build-graph: " + std::to_string(gaps) +
            " gap(s) between consecutive SUMO edges could not be bridged");
  return unmapped;
}

}  // namespace slamroute::roadgraph
