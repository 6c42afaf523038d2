// `postman`: optimal directed Chinese postman (every drivable edge at least once), made legal
// under SUMO turn permissions.
//
// Method (our choice, for the least added length we can reach and bound):
//  1. Turn-free optimum (lower bound): min-cost flow on the node imbalances in(i) - out(i)
//     (LEMON NetworkSimplex); every edge once plus the flow's duplicates.
//  2. Turn-legal optimum without connectivity: a min-cost circulation on the turn-expanded
//     (line) graph. Every edge e is split into e_in -> e_out with lower bound 1 and cost len(e);
//     every allowed turn e -> f is an arc e_out -> f_in of cost 0. The optimal circulation gives
//     how often each edge is driven and how often each legal turn is taken, with the least total
//     length: an exact turn-restricted postman *if* its support is connected.
//  3. Connect: the support may split into several closed trails. Two trails meeting at a
//     junction are merged for free by swapping their successors (a->a', b->b' becomes a->b',
//     b->a') when both new turns are legal; when only a->b' is legal, b->a' is replaced by the
//     shortest legal path from b to a' (cheapest first). Trails that still stay apart are joined
//     by the shortest legal closed walk to the main trail (Boost Dijkstra on the line graph).
//  4. Euler circuit (Hierholzer) on the line multigraph from an edge leaving the start node.
// Added length = (2) - (1) for turn permissions, plus the detours of (3); both in route.json.
#include <lemon/network_simplex.h>
#include <lemon/smart_graph.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

#include "Index.hpp"
#include "slamroute/core/UnionFind.hpp"
#include "slamroute/rl/Planners.hpp"

namespace slamroute::rl {

namespace {

long long mm(double metres) { return std::llround(metres * 1000.0); }

/// A turn: the index into pg.next of "drive `from`, then pg.next[turn]".
struct UsedTurn {
  int from, turn;
};

int turnIndex(const PlanGraph& pg, int e, int f) {
  for (int k = pg.nextBegin(e); k < pg.nextEnd(e); ++k)
    if (pg.next[sz(k)] == f) return k;
  return -1;
}

/// Step 2: how often each turn (index into pg.next) is taken in the cheapest legal covering
/// circulation.
std::vector<int> legalCirculation(const PlanGraph& pg, const std::vector<int>& forced) {
  using G = lemon::SmartDigraph;
  G lg;
  std::vector<G::Node> in(sz(pg.m)), out(sz(pg.m));
  for (int e = 0; e < pg.m; ++e) {
    in[sz(e)] = lg.addNode();
    out[sz(e)] = lg.addNode();
  }
  G::ArcMap<long long> lower(lg, 0), cost(lg, 0);
  for (int e = 0; e < pg.m; ++e) {
    const G::Arc a = lg.addArc(in[sz(e)], out[sz(e)]);
    lower[a] = 1;
    cost[a] = mm(pg.len[sz(e)]);
  }
  std::vector<G::Arc> turn(pg.next.size());
  for (int e = 0; e < pg.m; ++e)
    for (int k = pg.nextBegin(e); k < pg.nextEnd(e); ++k)
      turn[sz(k)] = lg.addArc(out[sz(e)], in[sz(pg.next[sz(k)])]);
  for (int k : forced) lower[turn[sz(k)]] = 1;
  lemon::NetworkSimplex<G, long long, long long> ns(lg);
  ns.lowerMap(lower).costMap(cost);
  if (ns.run() != lemon::NetworkSimplex<G, long long, long long>::OPTIMAL)
    throw std::runtime_error(
        "postman: no legal covering circulation (the turn graph is not "
        "strongly connected)");
  std::vector<int> y(pg.next.size());
  for (std::size_t k = 0; k < turn.size(); ++k) y[k] = static_cast<int>(ns.flow(turn[k]));
  return y;
}

/// Length driven by a circulation given as turn counts y.
double circulationLength(const PlanGraph& pg, const std::vector<int>& y) {
  double length = 0.0;
  for (int e = 0; e < pg.m; ++e)
    for (int k = pg.nextBegin(e); k < pg.nextEnd(e); ++k)
      length += y[sz(k)] * pg.len[sz(pg.next[sz(k)])];
  return length;
}

/// A circulation made one closed trail, with what the merging did.
struct Connection {
  std::vector<int> y;  ///< turn counts
  int swaps = 0, one_way = 0, detours = 0;
};

/// The closed trails of a circulation: edges joined by the turns it takes.
UnionFind supportComponents(const PlanGraph& pg, const std::vector<int>& y) {
  UnionFind trails(sz(pg.m));
  for (int e = 0; e < pg.m; ++e)
    for (int k = pg.nextBegin(e); k < pg.nextEnd(e); ++k)
      if (y[sz(k)] > 0) trails.unite(e, pg.next[sz(k)]);
  return trails;
}

/// The turns taken at junction j: arriving edge and turn index.
std::vector<UsedTurn> usedTurnsAt(const PlanGraph& pg, const std::vector<int>& arriving,
                                  const std::vector<int>& y) {
  std::vector<UsedTurn> used;
  for (int a : arriving)
    for (int k = pg.nextBegin(a); k < pg.nextEnd(a); ++k)
      if (y[sz(k)] > 0) used.push_back({a, k});
  return used;
}

/// Swaps the successors of two trails at one junction (a->a', b->b' becomes a->b', b->a') when
/// both new turns are legal. True when it merged two trails.
bool swapSuccessors(const PlanGraph& pg, const std::vector<UsedTurn>& used, std::vector<int>& y,
                    UnionFind& trails) {
  for (std::size_t p = 0; p < used.size(); ++p)
    for (std::size_t q = p + 1; q < used.size(); ++q) {
      const auto [a, ka] = used[p];
      const auto [b, kb] = used[q];
      if (trails.find(a) == trails.find(b)) continue;
      const int kab = turnIndex(pg, a, pg.next[sz(kb)]), kba = turnIndex(pg, b, pg.next[sz(ka)]);
      if (kab < 0 || kba < 0) continue;
      --y[sz(ka)], --y[sz(kb)], ++y[sz(kab)], ++y[sz(kba)];
      trails.unite(a, b);
      return true;
    }
  return false;
}

/// Rotates the successors of three trails at one junction (a->b', b->c', c->a'), which merges
/// trails where swaps cannot. True when it merged three trails.
bool rotateSuccessors(const PlanGraph& pg, const std::vector<UsedTurn>& used, std::vector<int>& y,
                      UnionFind& trails) {
  for (std::size_t p = 0; p < used.size(); ++p)
    for (std::size_t q = 0; q < used.size(); ++q)
      for (std::size_t r = 0; r < used.size(); ++r) {
        if (p == q || q == r || p == r) continue;
        const auto [a, ka] = used[p];
        const auto [b, kb] = used[q];
        const auto [c, kc] = used[r];
        const int root_a = trails.find(a), root_b = trails.find(b), root_c = trails.find(c);
        // Three distinct trails, else the rotation splits one.
        if (root_a == root_b || root_b == root_c || root_a == root_c) continue;
        if (ka == kb || kb == kc || ka == kc) continue;
        const int k1 = turnIndex(pg, a, pg.next[sz(kb)]);
        const int k2 = turnIndex(pg, b, pg.next[sz(kc)]);
        const int k3 = turnIndex(pg, c, pg.next[sz(ka)]);
        if (k1 < 0 || k2 < 0 || k3 < 0) continue;
        --y[sz(ka)], --y[sz(kb)], --y[sz(kc)], ++y[sz(k1)], ++y[sz(k2)], ++y[sz(k3)];
        trails.unite(a, b);
        trails.unite(a, c);
        return true;
      }
  return false;
}

/// Step 3a: free merges (swaps and rotations of successors at junctions).
void freeMerges(const PlanGraph& pg, const std::vector<std::vector<int>>& arriving,
                std::vector<int>& y, UnionFind& trails, int& swaps) {
  for (int j = 0; j < pg.n; ++j)
    while (true) {
      const std::vector<UsedTurn> used = usedTurnsAt(pg, arriving[sz(j)], y);
      if (!swapSuccessors(pg, used, y, trails) && !rotateSuccessors(pg, used, y, trails)) break;
      ++swaps;
    }
}

/// Adds a walk's turns to the circulation and joins its edges' trails.
void addWalk(const PlanGraph& pg, const std::vector<int>& walk, std::vector<int>& y,
             UnionFind& trails) {
  for (std::size_t i = 1; i < walk.size(); ++i) {
    ++y[sz(turnIndex(pg, walk[i - 1], walk[i]))];
    trails.unite(walk[0], walk[i]);
  }
}

/// A merge of two trails at a junction where trail A takes a->a' and trail B takes b->b', a->b'
/// is legal but b->a' is not: b->a' becomes the shortest legal path from b to a'.
struct OneWayMerge {
  double cost_m = std::numeric_limits<double>::infinity();
  int drop_a = -1, drop_b = -1, add = -1;
  std::vector<int> path;  ///< b, then the path's edges
};

void cheapestOneWayMergeAt(const PlanGraph& pg, const TurnPaths& paths,
                           const std::vector<UsedTurn>& used, UnionFind& trails,
                           OneWayMerge& best) {
  for (std::size_t p = 0; p < used.size(); ++p)
    for (std::size_t q = 0; q < used.size(); ++q) {
      const auto [a, ka] = used[p];
      const auto [b, kb] = used[q];
      if (p == q || trails.find(a) == trails.find(b)) continue;
      const int a2 = pg.next[sz(ka)];
      const int kab = turnIndex(pg, a, pg.next[sz(kb)]);
      if (kab < 0) continue;
      auto path = paths.toNearest(b, -1, [a2](int e) { return e == a2; });
      if (!path) continue;
      const double cost = path->length_m - pg.len[sz(a2)];
      if (cost < best.cost_m) {
        best.cost_m = cost;
        best.drop_a = ka, best.drop_b = kb, best.add = kab;
        best.path.assign(1, b);
        best.path.insert(best.path.end(), path->edges.begin(), path->edges.end());
      }
    }
}

/// Step 3b: one-way merges, the cheapest first, while there are any. Returns the added length.
double oneWayMerges(const PlanGraph& pg, const TurnPaths& paths,
                    const std::vector<std::vector<int>>& arriving, std::vector<int>& y,
                    UnionFind& trails, int& count) {
  double added_m = 0.0;
  while (trails.count() > 1) {
    OneWayMerge best;
    for (int j = 0; j < pg.n; ++j)
      cheapestOneWayMergeAt(pg, paths, usedTurnsAt(pg, arriving[sz(j)], y), trails, best);
    if (best.path.empty()) break;
    --y[sz(best.drop_a)], --y[sz(best.drop_b)], ++y[sz(best.add)];
    trails.unite(best.path.front(), pg.next[sz(best.add)]);
    addWalk(pg, best.path, y, trails);
    ++count;
    added_m += best.cost_m;
  }
  return added_m;
}

/// The shortest legal closed walk from the trail of c0 to the main trail (the one of e0), tried
/// from the first few edges of that trail.
std::vector<int> closedWalkToMain(const PlanGraph& pg, const TurnPaths& paths, UnionFind& trails,
                                  int c0, int e0, double& length_m) {
  const int comp = trails.find(c0);
  std::vector<int> best_walk;
  length_m = std::numeric_limits<double>::infinity();
  int tried = 0;
  for (int c = c0; c < pg.m && tried < 8; ++c) {
    if (trails.find(c) != comp) continue;
    ++tried;
    const int main_root = trails.find(e0);
    auto there = paths.toNearest(c, -1, [&](int e) { return trails.find(e) == main_root; });
    if (!there) continue;
    auto back = paths.toNearest(there->edges.back(), -1, [c](int e) { return e == c; });
    if (!back || there->length_m + back->length_m >= length_m) continue;
    length_m = there->length_m + back->length_m;
    best_walk.assign(1, c);
    best_walk.insert(best_walk.end(), there->edges.begin(), there->edges.end());
    best_walk.insert(best_walk.end(), back->edges.begin(), back->edges.end());
  }
  return best_walk;
}

/// Step 3c: closed walks from what is still apart to the main trail.
void closedWalkMerges(const PlanGraph& pg, const TurnPaths& paths, std::vector<int>& y,
                      UnionFind& trails, int e0, int& count) {
  for (int c0 = 0; c0 < pg.m; ++c0) {
    if (trails.find(c0) == trails.find(e0)) continue;
    double length_m = 0.0;
    const std::vector<int> walk = closedWalkToMain(pg, paths, trails, c0, e0, length_m);
    if (walk.empty())
      throw std::runtime_error("postman: cannot connect edge " + std::to_string(c0) +
                               " to the main circuit");
    addWalk(pg, walk, y, trails);
    trails.unite(e0, c0);
    ++count;
  }
}

/// What the planner needs throughout: the graph, its paths, the edges arriving at each node and
/// the first edge of the circuit.
struct PostmanGraph {
  const PlanGraph& pg;
  const TurnPaths& paths;
  std::vector<std::vector<int>> arriving;
  int e0;
  PostmanGraph(const PlanGraph& g, const TurnPaths& p, int start)
      : pg(g), paths(p), arriving(sz(g.n)), e0(g.out[sz(g.outBegin(start))]) {
    for (int e = 0; e < g.m; ++e) arriving[sz(g.v[sz(e)])].push_back(e);
  }
};

/// Step 3 on one circulation: free merges, then merges that cost a detour.
Connection connect(const PostmanGraph& g, std::vector<int> y) {
  Connection t;
  UnionFind trails = supportComponents(g.pg, y);
  freeMerges(g.pg, g.arriving, y, trails, t.swaps);
  if (trails.count() > 1) {
    oneWayMerges(g.pg, g.paths, g.arriving, y, trails, t.one_way);
    closedWalkMerges(g.pg, g.paths, y, trails, g.e0, t.detours);
  }
  t.y = std::move(y);
  return t;
}

/// The smallest trail apart from the main one (ties: the lowest root).
int smallestOtherTrail(UnionFind& trails, int m, int e0) {
  std::map<int, int> size;
  for (int e = 0; e < m; ++e) ++size[trails.find(e)];
  int small = -1;
  for (auto& [root, count] : size)
    if (root != trails.find(e0) && (small < 0 || count < size[small])) small = root;
  return small;
}

/// The cheapest circulation that also takes one unused legal turn into trail `small`; the
/// chosen turn is appended to `forced` (nothing when there is no such turn).
std::vector<int> cheapestForcing(const PlanGraph& pg, const std::vector<int>& y, UnionFind& trails,
                                 int small, std::vector<int>& forced) {
  double best_m = std::numeric_limits<double>::infinity();
  std::vector<int> best_y;
  int best_turn = -1;
  for (int e = 0; e < pg.m; ++e) {
    if (trails.find(e) == small) continue;
    for (int k = pg.nextBegin(e); k < pg.nextEnd(e); ++k) {
      if (trails.find(pg.next[sz(k)]) != small || y[sz(k)] > 0) continue;
      forced.push_back(k);
      std::vector<int> trial = legalCirculation(pg, forced);
      forced.pop_back();
      const double length_m = circulationLength(pg, trial);
      if (length_m < best_m) best_m = length_m, best_y = std::move(trial), best_turn = k;
    }
  }
  if (best_turn >= 0) forced.push_back(best_turn);
  return best_y;
}

/// Step 3, two ways, the shorter wins: (A) merge the trails of the optimal circulation y0 with
/// free swaps + detours; (B) re-solve the circulation forcing one legal turn into a still
/// separate trail (the flow re-routes optimally around it), a few rounds.
Connection connectBest(const PostmanGraph& g, const std::vector<int>& y0, int max_rounds,
                       int& forcing_rounds) {
  Connection best = connect(g, y0);
  double best_len = circulationLength(g.pg, best.y);
  std::vector<int> forced, y = y0;
  for (forcing_rounds = 0; forcing_rounds < max_rounds; ++forcing_rounds) {
    UnionFind trails = supportComponents(g.pg, y);
    int swaps = 0;
    std::vector<int> merged = y;
    freeMerges(g.pg, g.arriving, merged, trails, swaps);
    if (trails.count() == 1) break;
    const int small = smallestOtherTrail(trails, g.pg.m, g.e0);
    std::vector<int> forced_y = cheapestForcing(g.pg, y, trails, small, forced);
    if (forced_y.empty()) break;
    y = std::move(forced_y);
    Connection t = connect(g, y);
    const double length_m = circulationLength(g.pg, t.y);
    if (length_m < best_len) best = std::move(t), best_len = length_m;
  }
  return best;
}

/// Step 4: Hierholzer on the line multigraph with turn counts y, starting with e0. The circuit
/// returns to e0; the returned route ends at the start node.
std::vector<int> eulerCircuit(const PlanGraph& pg, std::vector<int> y, int e0) {
  std::vector<int> next_turn(pg.next_off.begin(), pg.next_off.end() - 1);
  std::vector<int> stack{e0}, circuit;
  while (!stack.empty()) {
    const int e = stack.back();
    int& k = next_turn[sz(e)];
    while (k < pg.nextEnd(e) && y[sz(k)] == 0) ++k;
    if (k < pg.nextEnd(e)) {
      --y[sz(k)];
      stack.push_back(pg.next[sz(k)]);
    } else {
      circuit.push_back(e);
      stack.pop_back();
    }
  }
  std::reverse(circuit.begin(), circuit.end());
  if (std::any_of(y.begin(), y.end(), [](int c) { return c != 0; }))
    throw std::logic_error("postman: Euler circuit left turns unused (disconnected support)");
  circuit.pop_back();
  return circuit;
}

/// An open route: the circuit up to the last edge driven for the first time.
void trimAfterLastNewEdge(std::vector<int>& circuit, int m) {
  std::vector<char> seen(sz(m), 0);
  std::size_t last_new = 0;
  for (std::size_t i = 0; i < circuit.size(); ++i)
    if (!seen[sz(circuit[i])]) seen[sz(circuit[i])] = 1, last_new = i;
  circuit.resize(last_new + 1);
}

}  // namespace

double turnFreePostmanLength(const PlanGraph& pg) {
  using G = lemon::SmartDigraph;
  G g;
  std::vector<G::Node> nodes(sz(pg.n));
  for (auto& x : nodes) x = g.addNode();
  G::ArcMap<long long> cost(g);
  G::NodeMap<long long> supply(g, 0);
  for (int e = 0; e < pg.m; ++e) {
    const G::Arc a = g.addArc(nodes[sz(pg.u[sz(e)])], nodes[sz(pg.v[sz(e)])]);
    cost[a] = mm(pg.len[sz(e)]);
    supply[nodes[sz(pg.v[sz(e)])]] += 1;  // supply = in - out: surplus arrivals must leave again
    supply[nodes[sz(pg.u[sz(e)])]] -= 1;
  }
  lemon::NetworkSimplex<G, long long, long long> ns(g);
  ns.costMap(cost).supplyMap(supply);
  if (ns.run() != lemon::NetworkSimplex<G, long long, long long>::OPTIMAL)
    throw std::runtime_error("postman: the graph is not strongly connected");
  return pg.total_edge_len + static_cast<double>(ns.totalCost()) / 1000.0;
}

PlanOutput planPostman(const PlanGraph& pg, const TurnPaths& paths, const Config& cfg, int start) {
  const double lower_bound = turnFreePostmanLength(pg);
  const PostmanGraph g(pg, paths, start);
  const std::vector<int> y0 = legalCirculation(pg, {});
  const double circulation_len = circulationLength(pg, y0);
  const int components = supportComponents(pg, y0).count();
  int forcing_rounds = 0;
  const Connection best = connectBest(g, y0, cfg.postman.max_forcing_rounds, forcing_rounds);

  PlanOutput out;
  out.edges = eulerCircuit(pg, best.y, g.e0);
  if (!cfg.postman.closed) trimAfterLastNewEdge(out.edges, pg.m);
  double length = 0.0;
  for (int e : out.edges) length += pg.len[sz(e)];
  out.stats = PostmanStats{lower_bound,
                           circulation_len,
                           components,
                           best.swaps,
                           forcing_rounds,
                           best.one_way,
                           best.detours,
                           circulationLength(pg, best.y) - circulation_len,
                           lower_bound > 0 ? 100.0 * (length / lower_bound - 1.0) : 0.0};
  return out;
}

}  // namespace slamroute::rl
