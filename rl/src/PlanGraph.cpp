// Building the planning graph (largest legally drivable part) and turn-aware shortest paths.
#include "slamroute/rl/PlanGraph.hpp"

// Boost 1.74's adjacency_list edge iterator trips GCC's -Wmaybe-uninitialized (a false positive
// inside Boost); silenced for this file only.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"

#include <algorithm>
#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/dijkstra_shortest_paths.hpp>
#include <boost/graph/strong_components.hpp>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

#include "Index.hpp"

namespace slamroute::rl {

namespace {

using LineGraph = boost::adjacency_list<boost::vecS, boost::vecS, boost::directedS>;

/// The strongly connected parts of the line graph (edge e -> f for every allowed turn) and the
/// largest one that a route can drive.
struct TurnComponents {
  std::vector<std::vector<int>> nexts;  ///< allowed successors per edge
  std::vector<int> comp;                ///< component per edge
  int largest = -1;                     ///< the largest component with a cycle
};

/// A component is drivable when it has a cycle: more than one edge, or an edge with a self-turn.
bool hasCycle(const TurnComponents& tc, int c, int size) {
  if (size > 1) return true;
  for (std::size_t e = 0; e < tc.comp.size(); ++e)
    if (tc.comp[e] == c)
      for (int f : tc.nexts[e])
        if (f == static_cast<int>(e)) return true;
  return false;
}

TurnComponents turnComponents(const RoadGraph& g, const std::string& where) {
  const int m0 = static_cast<int>(g.edges.size());
  TurnComponents tc;
  LineGraph lg(sz(m0));
  tc.nexts.resize(sz(m0));
  for (int e = 0; e < m0; ++e) {
    tc.nexts[sz(e)] = g.nextEdges(e);
    for (int f : tc.nexts[sz(e)]) boost::add_edge(sz(e), sz(f), lg);
  }
  tc.comp.resize(sz(m0));
  const int ncomp = boost::strong_components(
      lg, boost::make_iterator_property_map(tc.comp.begin(), boost::get(boost::vertex_index, lg)));
  std::vector<int> count(sz(ncomp), 0);
  for (int c : tc.comp) ++count[sz(c)];
  for (int c = 0; c < ncomp; ++c)
    if (hasCycle(tc, c, count[sz(c)]) && (tc.largest < 0 || count[sz(c)] > count[sz(tc.largest)]))
      tc.largest = c;
  if (tc.largest < 0)
    throw std::invalid_argument(where +
                                ": no route can be driven legally (no cycle under the turn "
                                "permissions)");
  return tc;
}

/// Numbers the nodes and edges of the largest component locally; returns the local id of each
/// original edge (-1 outside it).
std::vector<int> keepLargest(PlanGraph& pg, const RoadGraph& g, const TurnComponents& tc) {
  const int m0 = static_cast<int>(g.edges.size());
  pg.node_local.assign(g.nodes.size(), -1);
  std::vector<int> edge_local(sz(m0), -1);
  for (int e = 0; e < m0; ++e) {
    if (tc.comp[sz(e)] != tc.largest) continue;
    const RoadEdge& re = g.edges[sz(e)];
    for (int x : {re.u, re.v})
      if (pg.node_local[sz(x)] < 0) {
        pg.node_local[sz(x)] = pg.n++;
        pg.node_orig.push_back(x);
      }
    edge_local[sz(e)] = pg.m++;
    pg.edge_orig.push_back(e);
  }
  pg.dropped_nodes = static_cast<int>(g.nodes.size()) - pg.n;
  pg.dropped_edges = m0 - pg.m;
  return edge_local;
}

/// Per local edge: ends, length, normalised weight, heading and street; counts out-edges.
void addEdges(PlanGraph& pg, const RoadGraph& g) {
  double wmax = 0.0;
  for (int e : pg.edge_orig) wmax = std::max(wmax, g.edges[sz(e)].weight);
  std::map<int, int> street_id;
  pg.out_off.assign(sz(pg.n) + 1, 0);
  for (int le = 0; le < pg.m; ++le) {
    const RoadEdge& re = g.edges[sz(pg.edge_orig[sz(le)])];
    const int lu = pg.node_local[sz(re.u)], lv = pg.node_local[sz(re.v)];
    pg.u.push_back(lu);
    pg.v.push_back(lv);
    pg.len.push_back(std::max(re.length_m, 0.0));
    pg.weight.push_back(wmax > 0.0 ? std::clamp(re.weight / wmax, 0.0, 1.0) : 1.0);
    const Point3& a = g.nodes[sz(re.u)].pos;
    const Point3& b = g.nodes[sz(re.v)].pos;
    pg.heading.push_back(std::atan2(b.y() - a.y(), b.x() - a.x()));
    const int key = re.street >= 0 ? re.street : -1 - re.id;
    auto [it, inserted] = street_id.try_emplace(key, pg.num_streets);
    if (inserted) {
      ++pg.num_streets;
      pg.street_len.push_back(0.0);
    }
    pg.street.push_back(it->second);
    pg.street_len[sz(it->second)] = std::max(pg.street_len[sz(it->second)], pg.len.back());
    ++pg.out_off[sz(lu) + 1];
    pg.total_edge_len += pg.len.back();
  }
}

/// The out-edges per node and the allowed next edges per edge, both as CSR arrays.
void linkEdges(PlanGraph& pg, const TurnComponents& tc, const std::vector<int>& edge_local) {
  for (int i = 0; i < pg.n; ++i) pg.out_off[sz(i) + 1] += pg.out_off[sz(i)];
  pg.out.assign(sz(pg.m), 0);
  std::vector<int> fill(pg.out_off.begin(), pg.out_off.end() - 1);
  for (int le = 0; le < pg.m; ++le) pg.out[sz(fill[sz(pg.u[sz(le)])]++)] = le;
  pg.next_off.assign(sz(pg.m) + 1, 0);
  for (int le = 0; le < pg.m; ++le) {
    for (int f : tc.nexts[sz(pg.edge_orig[sz(le)])])
      if (edge_local[sz(f)] >= 0) pg.next.push_back(edge_local[sz(f)]);
    pg.next_off[sz(le) + 1] = static_cast<int>(pg.next.size());
  }
}

}  // namespace

PlanGraph PlanGraph::build(const RoadGraph& g, const std::string& where) {
  if (g.nodes.empty() || g.edges.empty())
    throw std::invalid_argument(where + ": the graph is empty (no nodes or no edges)");
  g.validate(where);
  const TurnComponents tc = turnComponents(g, where);
  PlanGraph pg;
  pg.restricted = g.restricted_turns;
  const std::vector<int> edge_local = keepLargest(pg, g, tc);
  addEdges(pg, g);
  linkEdges(pg, tc, edge_local);
  for (double l : pg.street_len) pg.total_street_len += l;
  pg.mean_len = std::max(pg.total_edge_len / pg.m, 1e-6);
  return pg;
}

// ---------------------------------------------------------------------------------------------

struct TurnPaths::Impl {
  using G = boost::adjacency_list<boost::vecS, boost::vecS, boost::directedS, boost::no_property,
                                  boost::property<boost::edge_weight_t, double>>;
  G g;
};

namespace {
struct Found {
  std::size_t vertex;
};
template <class Pred>
struct StopAt : boost::default_dijkstra_visitor {
  Pred pred;
  explicit StopAt(Pred p) : pred(p) {}
  template <class V, class G>
  void examine_vertex(V x, const G&) {
    if (pred(x)) throw Found{x};
  }
};
}  // namespace

TurnPaths::TurnPaths(const PlanGraph& pg) : pg_(pg), impl_(std::make_shared<Impl>()) {
  impl_->g = Impl::G(sz(pg.m + pg.n));
  for (int e = 0; e < pg.m; ++e)
    for (int k = pg.nextBegin(e); k < pg.nextEnd(e); ++k) {
      const int f = pg.next[sz(k)];
      boost::add_edge(sz(e), sz(f), pg.len[sz(f)], impl_->g);
    }
  for (int i = 0; i < pg.n; ++i)
    for (int k = pg.outBegin(i); k < pg.outEnd(i); ++k) {
      const int f = pg.out[sz(k)];
      boost::add_edge(sz(pg.m + i), sz(f), pg.len[sz(f)], impl_->g);
    }
}

void TurnPaths::run(int from_edge, int from_node, std::vector<double>& dist,
                    std::vector<int>& pred) const {
  const std::size_t nv = boost::num_vertices(impl_->g);
  const std::size_t src = from_edge >= 0 ? sz(from_edge) : sz(pg_.m + from_node);
  dist.assign(nv, std::numeric_limits<double>::infinity());
  std::vector<std::size_t> p(nv);
  boost::dijkstra_shortest_paths(impl_->g, src,
                                 boost::predecessor_map(p.data()).distance_map(dist.data()));
  pred.assign(nv, -1);
  for (std::size_t x = 0; x < nv; ++x)
    if (p[x] != x) pred[x] = static_cast<int>(p[x]);
}

std::vector<double> TurnPaths::distances(int from_edge, int from_node) const {
  std::vector<double> dist;
  std::vector<int> pred;
  run(from_edge, from_node, dist, pred);
  dist.resize(sz(pg_.m));
  return dist;
}

std::optional<TurnPaths::Path> TurnPaths::toNearest(int from_edge, int from_node,
                                                    const std::function<bool(int)>& goal) const {
  const std::size_t nv = boost::num_vertices(impl_->g);
  const std::size_t src = from_edge >= 0 ? sz(from_edge) : sz(pg_.m + from_node);
  std::vector<double> dist(nv, std::numeric_limits<double>::infinity());
  std::vector<std::size_t> p(nv);
  for (std::size_t x = 0; x < nv; ++x) p[x] = x;
  const int m = pg_.m;
  auto is_goal = [&, src](std::size_t x) {
    return x != src && static_cast<int>(x) < m && goal(static_cast<int>(x));
  };
  std::size_t hit = nv;
  try {
    boost::dijkstra_shortest_paths(
        impl_->g, src,
        boost::predecessor_map(p.data()).distance_map(dist.data()).visitor(StopAt(is_goal)));
  } catch (const Found& f) {
    hit = f.vertex;
  }
  if (hit == nv) return std::nullopt;
  Path path;
  path.length_m = dist[hit];
  for (std::size_t x = hit; x != src; x = p[x]) {
    path.edges.push_back(static_cast<int>(x));
    if (p[x] == x) return std::nullopt;  // defensive: broken predecessor chain
  }
  std::reverse(path.edges.begin(), path.edges.end());
  return path;
}

}  // namespace slamroute::rl
