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
#include <cstdio>
#include <cstdlib>
#include <map>
#include <cmath>
#include <nlohmann/json.hpp>
#include <limits>
#include <numeric>
#include <stdexcept>

#include "slamroute/rl/Planners.hpp"

namespace slamroute::rl {

namespace {

std::size_t sz(int i) { return static_cast<std::size_t>(i); }
long long mm(double metres) { return std::llround(metres * 1000.0); }

struct UnionFind {
  std::vector<int> p;
  explicit UnionFind(int n) : p(sz(n)) { std::iota(p.begin(), p.end(), 0); }
  int find(int x) {
    while (p[sz(x)] != x) x = p[sz(x)] = p[sz(p[sz(x)])];
    return x;
  }
  bool unite(int a, int b) {
    a = find(a);
    b = find(b);
    if (a == b) return false;
    p[sz(b)] = a;
    return true;
  }
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
    throw std::runtime_error("postman: no legal covering circulation (the turn graph is not "
                             "strongly connected)");
  std::vector<int> y(pg.next.size());
  for (std::size_t k = 0; k < turn.size(); ++k) y[k] = static_cast<int>(ns.flow(turn[k]));
  return y;
}

struct Trails {
  std::vector<int> y;  ///< turn counts
  int swaps = 0, one_way = 0, detours = 0;
  double detour_len = 0.0;
  double length(const PlanGraph& pg) const {
    double l = 0.0;
    for (int e = 0; e < pg.m; ++e)
      for (int k = pg.nextBegin(e); k < pg.nextEnd(e); ++k) l += y[sz(k)] * pg.len[sz(pg.next[sz(k)])];
    return l;
  }
};

UnionFind supportComponents(const PlanGraph& pg, const std::vector<int>& y) {
  UnionFind uf(pg.m);
  for (int e = 0; e < pg.m; ++e)
    for (int k = pg.nextBegin(e); k < pg.nextEnd(e); ++k)
      if (y[sz(k)] > 0) uf.unite(e, pg.next[sz(k)]);
  return uf;
}

int countRoots(UnionFind& uf, int m) {
  int c = 0;
  for (int e = 0; e < m; ++e) c += uf.find(e) == e ? 1 : 0;
  return c;
}

/// Step 3a: free merges (swaps and rotations of successors at junctions).
void freeMerges(const PlanGraph& pg, const std::vector<std::vector<int>>& into, std::vector<int>& y,
                UnionFind& uf, int& swaps) {
  for (int j = 0; j < pg.n; ++j) {
    bool merged = true;
    while (merged) {
      merged = false;
      std::vector<std::pair<int, int>> used;  // (from edge, turn index)
      for (int a : into[sz(j)])
        for (int k = pg.nextBegin(a); k < pg.nextEnd(a); ++k)
          if (y[sz(k)] > 0) used.emplace_back(a, k);
      for (std::size_t p = 0; p < used.size() && !merged; ++p)
        for (std::size_t q = p + 1; q < used.size() && !merged; ++q) {
          const auto [a, ka] = used[p];
          const auto [b, kb] = used[q];
          if (uf.find(a) == uf.find(b)) continue;
          const int a2 = pg.next[sz(ka)], b2 = pg.next[sz(kb)];
          const int kab = turnIndex(pg, a, b2), kba = turnIndex(pg, b, a2);
          if (kab < 0 || kba < 0) continue;
          --y[sz(ka)], --y[sz(kb)], ++y[sz(kab)], ++y[sz(kba)];
          uf.unite(a, b);
          ++swaps;
          merged = true;
        }
      // Rotations of three successors (a->b', b->c', c->a') merge trails where swaps cannot.
      for (std::size_t p = 0; p < used.size() && !merged; ++p)
        for (std::size_t q = 0; q < used.size() && !merged; ++q)
          for (std::size_t r = 0; r < used.size() && !merged; ++r) {
            if (p == q || q == r || p == r) continue;
            const auto [a, ka] = used[p];
            const auto [b, kb] = used[q];
            const auto [c, kc] = used[r];
            const int ra = uf.find(a), rb = uf.find(b), rc = uf.find(c);
            if (ra == rb || rb == rc || ra == rc) continue;  // three distinct trails, else it splits
            if (ka == kb || kb == kc || ka == kc) continue;
            const int k1 = turnIndex(pg, a, pg.next[sz(kb)]);
            const int k2 = turnIndex(pg, b, pg.next[sz(kc)]);
            const int k3 = turnIndex(pg, c, pg.next[sz(ka)]);
            if (k1 < 0 || k2 < 0 || k3 < 0) continue;
            --y[sz(ka)], --y[sz(kb)], --y[sz(kc)], ++y[sz(k1)], ++y[sz(k2)], ++y[sz(k3)];
            uf.unite(a, b);
            uf.unite(a, c);
            ++swaps;
            merged = true;
          }
    }
  }
}

/// Steps 3b-3c: merges that cost a detour.
void detourMerges(const PlanGraph& pg, const TurnPaths& paths, const std::vector<std::vector<int>>& into,
                  std::vector<int>& y, UnionFind& uf, int e0, Trails& t) {
  int& one_way = t.one_way;
  int& detours = t.detours;
  double& detour_len = t.detour_len;
  // Step 3b: merges that need one detour: at a junction where trail A takes a->a' and trail B
  // takes b->b', with a->b' legal but b->a' not, replace b->a' by the shortest legal path from b
  // to a'. The cheapest such merge is applied first, repeatedly. What still stays apart is
  // joined by the shortest legal closed walk to the main trail (step 3c).
  auto addWalk = [&](const std::vector<int>& walk) {
    for (std::size_t i = 1; i < walk.size(); ++i) {
      ++y[sz(turnIndex(pg, walk[i - 1], walk[i]))];
      uf.unite(walk[0], walk[i]);
    }
  };
  while (countRoots(uf, pg.m) > 1) {
    double best = std::numeric_limits<double>::infinity();
    int best_drop1 = -1, best_drop2 = -1, best_add = -1;
    std::vector<int> best_path;
    for (int j = 0; j < pg.n; ++j) {
      std::vector<std::pair<int, int>> used;
      for (int a : into[sz(j)])
        for (int k = pg.nextBegin(a); k < pg.nextEnd(a); ++k)
          if (y[sz(k)] > 0) used.emplace_back(a, k);
      for (std::size_t p = 0; p < used.size(); ++p)
        for (std::size_t q = 0; q < used.size(); ++q) {
          const auto [a, ka] = used[p];
          const auto [b, kb] = used[q];
          if (p == q || uf.find(a) == uf.find(b)) continue;
          const int a2 = pg.next[sz(ka)], b2 = pg.next[sz(kb)];
          const int kab = turnIndex(pg, a, b2);
          if (kab < 0) continue;
          auto path = paths.toNearest(b, -1, [a2](int e) { return e == a2; });
          if (!path) continue;
          const double cost = path->length_m - pg.len[sz(a2)];
          if (cost < best) {
            best = cost;
            best_drop1 = ka, best_drop2 = kb, best_add = kab;
            best_path.assign(1, b);
            best_path.insert(best_path.end(), path->edges.begin(), path->edges.end());
          }
        }
    }
    if (best_path.empty()) break;
    --y[sz(best_drop1)], --y[sz(best_drop2)], ++y[sz(best_add)];
    uf.unite(best_path.front(), pg.next[sz(best_add)]);
    addWalk(best_path);
    ++one_way;
    detour_len += best;
  }
  // Step 3c: closed walks from what is left to the main trail.
  for (int c0 = 0; c0 < pg.m; ++c0) {
    if (uf.find(c0) == uf.find(e0)) continue;
    const int comp = uf.find(c0);
    std::vector<int> best_walk;
    double best = std::numeric_limits<double>::infinity();
    int tried = 0;
    for (int c = c0; c < pg.m && tried < 8; ++c) {
      if (uf.find(c) != comp) continue;
      ++tried;
      const int main_root = uf.find(e0);
      auto p1 = paths.toNearest(c, -1, [&](int e) { return uf.find(e) == main_root; });
      if (!p1) continue;
      auto p2 = paths.toNearest(p1->edges.back(), -1, [c](int e) { return e == c; });
      if (!p2 || p1->length_m + p2->length_m >= best) continue;
      best = p1->length_m + p2->length_m;
      best_walk.assign(1, c);
      best_walk.insert(best_walk.end(), p1->edges.begin(), p1->edges.end());
      best_walk.insert(best_walk.end(), p2->edges.begin(), p2->edges.end());
    }
    if (best_walk.empty())
      throw std::runtime_error("postman: cannot connect edge " + std::to_string(c0) +
                               " to the main circuit");
    addWalk(best_walk);
    uf.unite(e0, c0);
    ++detours;
    detour_len += best;
  }

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
  const int e0 = pg.out[sz(pg.outBegin(start))];
  std::vector<std::vector<int>> into(sz(pg.n));
  for (int e = 0; e < pg.m; ++e) into[sz(pg.v[sz(e)])].push_back(e);
  std::vector<int> forced;
  const std::vector<int> y0 = legalCirculation(pg, forced);
  Trails first;
  first.y = y0;
  const double circulation_len = first.length(pg);
  UnionFind uf0 = supportComponents(pg, y0);
  const int components = countRoots(uf0, pg.m);

  // Connect (step 3), two ways, the shorter wins: (A) merge the trails of the optimal
  // circulation with free swaps + detours; (B) re-solve the circulation forcing one legal turn
  // into a still separate trail (the flow re-routes optimally around it), a few rounds.
  auto connect = [&](std::vector<int> y) {
    Trails t;
    UnionFind uf = supportComponents(pg, y);
    freeMerges(pg, into, y, uf, t.swaps);
    if (countRoots(uf, pg.m) > 1) detourMerges(pg, paths, into, y, uf, e0, t);
    t.y = std::move(y);
    return t;
  };
  Trails best = connect(y0);
  double best_len = best.length(pg);
  int forced_rounds = 0;
  std::vector<int> y = y0;
  for (int round = 0; round < cfg.postman.max_forcing_rounds; ++round) {
    UnionFind uf = supportComponents(pg, y);
    int swaps = 0;
    std::vector<int> ym = y;
    freeMerges(pg, into, ym, uf, swaps);
    if (countRoots(uf, pg.m) == 1) break;
    // The smallest trail not containing e0: try forcing each legal turn into it.
    std::map<int, int> size;
    for (int e = 0; e < pg.m; ++e) ++size[uf.find(e)];
    int small = -1;
    for (auto& [r, s] : size)
      if (r != uf.find(e0) && (small < 0 || s < size[small])) small = r;
    double trial_best = std::numeric_limits<double>::infinity();
    std::vector<int> trial_y;
    int trial_k = -1;
    for (int e = 0; e < pg.m; ++e) {
      if (uf.find(e) == small) continue;
      for (int k = pg.nextBegin(e); k < pg.nextEnd(e); ++k) {
        if (uf.find(pg.next[sz(k)]) != small || y[sz(k)] > 0) continue;
        forced.push_back(k);
        std::vector<int> yt = legalCirculation(pg, forced);
        forced.pop_back();
        Trails tt;
        tt.y = yt;
        const double l = tt.length(pg);
        if (l < trial_best) trial_best = l, trial_y = std::move(yt), trial_k = k;
      }
    }
    if (trial_k < 0) break;
    forced.push_back(trial_k);
    y = trial_y;
    ++forced_rounds;
    Trails t = connect(y);
    const double l = t.length(pg);
    if (l < best_len) best = std::move(t), best_len = l;
  }
  std::vector<int>& yb = best.y;
  const int swaps = best.swaps, one_way = best.one_way, detours = best.detours;
  const double detour_len = best_len - circulation_len;
  y = yb;

  // Step 4: Hierholzer on the line multigraph, starting with e0.
  std::vector<int> ptr(pg.next_off.begin(), pg.next_off.end() - 1);
  std::vector<int> stack{e0}, circuit;
  while (!stack.empty()) {
    const int e = stack.back();
    int& k = ptr[sz(e)];
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
  circuit.pop_back();  // the circuit returns to e0; the route ends at the start node
  if (!cfg.postman.closed) {
    std::vector<char> seen(sz(pg.m), 0);
    std::size_t last_new = 0;
    for (std::size_t i = 0; i < circuit.size(); ++i)
      if (!seen[sz(circuit[i])]) seen[sz(circuit[i])] = 1, last_new = i;
    circuit.resize(last_new + 1);
  }

  PlanOutput out;
  out.edges = std::move(circuit);
  double length = 0.0;
  for (int e : out.edges) length += pg.len[sz(e)];
  out.extra_json = nlohmann::json{{"turn_free_optimum_m", lower_bound},
                                  {"legal_circulation_m", circulation_len},
                                  {"trails_before_merge", components},
                                  {"free_merges", swaps},
                                  {"forcing_rounds", forced_rounds},
                                  {"one_way_detours", one_way},
                                  {"closed_walk_detours", detours},
                                  {"detour_length_m", detour_len},
                                  {"excess_over_turn_free_pct",
                                   lower_bound > 0 ? 100.0 * (length / lower_bound - 1.0) : 0.0}}
                       .dump();
  return out;
}

}  // namespace slamroute::rl
