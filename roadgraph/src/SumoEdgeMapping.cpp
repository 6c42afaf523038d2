// Mapping of graph edges to the SUMO edges they cover, so routes on the graph can be driven in
// SUMO: each edge's polyline is walked along the net's passenger lanes in its direction of travel.
#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

#include "PointGrid.hpp"
#include "slamroute/core/Log.hpp"
#include "slamroute/roadgraph/SumoMatch.hpp"

namespace slamroute::roadgraph {
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
  /// Length of the bridge a -> b [m]: 0 when b follows a directly, infinity when none joins them.
  double bridgeLengthM(int a, int b) const {
    if (turnAllowed(a, b)) return 0.0;
    const auto path = bridge(a, b);
    if (path.empty()) return std::numeric_limits<double>::infinity();
    double len = 0.0;
    for (const auto& id : path)
      if (const SumoEdge* e = id == "." ? nullptr : net_.findEdge(id)) len += e->length();
    return len;
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

/// SUMO edges along a polyline in order, each with the number of samples that matched it and
/// where along the polyline its first and last sample lie [m].
struct EdgeRun {
  std::vector<int> edge, samples;
  std::vector<double> first_m, last_m;
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
        run.first_m.push_back(pos);
        run.last_m.push_back(pos);
      }
      ++run.samples.back();
      run.last_m.back() = pos;
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
      run.last_m[k - 1] = run.last_m[k + 1];
      const auto dropTwo = [k](auto& v) {
        v.erase(v.begin() + static_cast<long>(k), v.begin() + static_cast<long>(k) + 2);
      };
      dropTwo(seq);
      dropTwo(cnt);
      dropTwo(run.first_m);
      dropTwo(run.last_m);
      k = std::max<std::size_t>(1, k - 1);
    } else {
      ++k;
    }
  }
}

/// Keeps the drivable chain with the most samples (longest path in the DAG of the sequence
/// whose links are allowed turns or bridgeable within 4 edges): samples snapping to the other
/// carriageway or a crossing street for a few steps cannot be driven and are dropped. A bridge
/// longer than the stretch of polyline between the two matches costs the samples its excess
/// length would hold: a sample or two on the opposite lane at a corner would otherwise keep a
/// chain that drives to the next junction and back to reach it. Returns the SUMO edges of the
/// chain; adds the matches dropped to `dropped`.
std::vector<int> drivableChain(const EdgeRun& run, const SumoLanes& lanes,
                               const SumoMatchConfig& cfg, std::size_t& dropped) {
  const std::vector<int>& seq = run.edge;
  if (seq.size() <= 1) return seq;
  const std::size_t m = seq.size();
  std::map<std::pair<int, int>, double> bridges;
  auto bridgeLength = [&](int a, int b) {
    if (a == b) return 0.0;
    const auto [it, fresh] = bridges.try_emplace({a, b}, 0.0);
    if (fresh) it->second = lanes.bridgeLengthM(a, b);
    return it->second;
  };
  const auto cost = [&](std::size_t j, std::size_t k) {
    const double gap = run.first_m[k] - run.last_m[j];
    return std::max(0.0, bridgeLength(seq[j], seq[k]) - gap) / cfg.sample_step_m;
  };
  std::vector<double> score(m, 0.0);
  std::vector<int> parent(m, -1);
  for (std::size_t k = 0; k < m; ++k) {
    score[k] = run.samples[k];
    for (std::size_t j = 0; j < k; ++j)
      if (score[j] + run.samples[k] > score[k]) {
        const double with_j = score[j] + run.samples[k] - cost(j, k);
        if (with_j > score[k]) {
          score[k] = with_j;
          parent[k] = static_cast<int>(j);
        }
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
    std::vector<int> chain = drivableChain(run, lanes, cfg, dropped);
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
