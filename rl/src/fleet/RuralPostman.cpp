// Directed rural postman under turn permissions, in three steps:
//  1. The cheapest circulation on the turn-expanded graph that drives every required edge and
//     passes the depot exactly once (LEMON NetworkSimplex). The depot is one extra vertex: arcs
//     from it to the edges leaving the depot junction, arcs to it from the edges arriving there.
//  2. Trails of that circulation that meet at a junction are merged for free by swapping their
//     successors where both new turns are allowed. A part still apart from the depot's part is
//     joined by the shortest legal closed walk from it to the depot's part and back: the walk's
//     edges become required and the circulation is solved again (a few rounds); what still stays
//     apart gets the walk added.
//  3. Hierholzer's Euler circuit from the depot vertex gives the edge sequence.
// The same line-graph circulation idea as the single-vehicle postman, with lower bounds only on
// the required edges and a depot vertex, so a vehicle leaves its depot and comes back to it.
#include "RuralPostman.hpp"

#include <lemon/network_simplex.h>
#include <lemon/smart_graph.h>

#include <cmath>
#include <limits>
#include <numeric>
#include <queue>
#include <stdexcept>

namespace slamroute::rl::fleet {
namespace {

std::size_t sz(int i) { return static_cast<std::size_t>(i); }

/// Re-solves of the circulation to join its parts (each costs one network simplex run).
constexpr int kJoinRounds = 32;
long long mm(double metres) { return std::llround(metres * 1000.0); }

/// How often each arc of the turn graph with the depot vertex is used.
struct Circulation {
  std::vector<int> turn;    ///< per turn index k (into pg.next)
  std::vector<int> leave;   ///< per edge: drives it first from the depot
  std::vector<int> arrive;  ///< per edge: returns to the depot after it
};

struct Components {
  std::vector<int> parent;
  explicit Components(int n) : parent(sz(n)) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int x) {
    while (parent[sz(x)] != x) x = parent[sz(x)] = parent[sz(parent[sz(x)])];
    return x;
  }
  void unite(int a, int b) { parent[sz(find(b))] = find(a); }
};

int findTurn(const PlanGraph& pg, int e, int f) {
  for (int k = pg.nextBegin(e); k < pg.nextEnd(e); ++k)
    if (pg.next[sz(k)] == f) return k;
  return -1;
}

int turnIndex(const PlanGraph& pg, int e, int f) {
  const int k = findTurn(pg, e, f);
  if (k < 0) throw std::logic_error("rural postman: a shortest path took a forbidden turn");
  return k;
}

Circulation cheapestCirculation(const PlanGraph& pg, const std::vector<char>& required, int depot) {
  using G = lemon::SmartDigraph;
  using Simplex = lemon::NetworkSimplex<G, long long, long long>;
  G lg;
  std::vector<G::Node> in(sz(pg.m)), out(sz(pg.m));
  for (int e = 0; e < pg.m; ++e) in[sz(e)] = lg.addNode(), out[sz(e)] = lg.addNode();
  const G::Node dIn = lg.addNode(), dOut = lg.addNode();
  std::vector<G::Arc> drive(sz(pg.m)), turn(pg.next.size()), leave(sz(pg.m), lemon::INVALID),
      arrive(sz(pg.m), lemon::INVALID);
  for (int e = 0; e < pg.m; ++e) {
    drive[sz(e)] = lg.addArc(in[sz(e)], out[sz(e)]);
    for (int k = pg.nextBegin(e); k < pg.nextEnd(e); ++k)
      turn[sz(k)] = lg.addArc(out[sz(e)], in[sz(pg.next[sz(k)])]);
    if (pg.u[sz(e)] == depot) leave[sz(e)] = lg.addArc(dOut, in[sz(e)]);
    if (pg.v[sz(e)] == depot) arrive[sz(e)] = lg.addArc(out[sz(e)], dIn);
  }
  const G::Arc once = lg.addArc(dIn, dOut);
  // Maps made after the arcs (arcs added later would get 0, not the fill value). A finite
  // capacity: no edge needs to be driven more often than there are edges.
  G::ArcMap<long long> lower(lg, 0), upper(lg, 4LL * pg.m + 4), cost(lg, 0);
  for (int e = 0; e < pg.m; ++e) {
    lower[drive[sz(e)]] = required[sz(e)] ? 1 : 0;
    cost[drive[sz(e)]] = mm(pg.len[sz(e)]);
  }
  lower[once] = upper[once] = 1;
  Simplex ns(lg);
  ns.lowerMap(lower).upperMap(upper).costMap(cost);
  if (ns.run() != Simplex::OPTIMAL)
    throw std::runtime_error(
        "rural postman: the required streets cannot be driven in a legal "
        "round trip from the depot");
  Circulation c{std::vector<int>(turn.size()), std::vector<int>(sz(pg.m)),
                std::vector<int>(sz(pg.m))};
  for (std::size_t k = 0; k < turn.size(); ++k) c.turn[k] = static_cast<int>(ns.flow(turn[k]));
  for (int e = 0; e < pg.m; ++e) {
    if (leave[sz(e)] != lemon::INVALID) c.leave[sz(e)] = static_cast<int>(ns.flow(leave[sz(e)]));
    if (arrive[sz(e)] != lemon::INVALID) c.arrive[sz(e)] = static_cast<int>(ns.flow(arrive[sz(e)]));
  }
  return c;
}

/// Vertices 0..m-1 are edge states, m is the depot; joined when an arc between them is used.
Components usedParts(const PlanGraph& pg, const Circulation& c, std::vector<char>& used) {
  Components parts(pg.m + 1);
  used.assign(sz(pg.m), 0);
  for (int e = 0; e < pg.m; ++e) {
    for (int k = pg.nextBegin(e); k < pg.nextEnd(e); ++k)
      if (c.turn[sz(k)] > 0) parts.unite(e, pg.next[sz(k)]), used[sz(pg.next[sz(k)])] = 1;
    if (c.leave[sz(e)] > 0) parts.unite(pg.m, e), used[sz(e)] = 1;
    if (c.arrive[sz(e)] > 0) parts.unite(pg.m, e);
  }
  return parts;
}

/// A used arc at a junction: edge `from` continues with edge `to`, or returns to the depot
/// (to = -1) when the junction is the depot.
struct Successor {
  int from, to;
};

std::vector<Successor> successorsAt(const PlanGraph& pg, const Circulation& c,
                                    const std::vector<int>& into) {
  std::vector<Successor> out;
  for (int a : into) {
    for (int k = pg.nextBegin(a); k < pg.nextEnd(a); ++k)
      if (c.turn[sz(k)] > 0) out.push_back({a, pg.next[sz(k)]});
    if (c.arrive[sz(a)] > 0) out.push_back({a, -1});
  }
  return out;
}

void moveArc(const PlanGraph& pg, Circulation& c, int from, int to, int delta) {
  if (to < 0)
    c.arrive[sz(from)] += delta;
  else
    c.turn[sz(turnIndex(pg, from, to))] += delta;
}

/// At one junction: two trails that pass it, a -> a2 and b -> b2, become one when both a -> b2
/// and b -> a2 are allowed (same length, the successors swapped). Returns true after a swap.
bool swapOnce(const PlanGraph& pg, Circulation& c, const std::vector<int>& into,
              Components& parts) {
  const std::vector<Successor> used = successorsAt(pg, c, into);
  for (std::size_t p = 0; p < used.size(); ++p)
    for (std::size_t q = p + 1; q < used.size(); ++q) {
      const Successor x = used[p], y = used[q];
      if (parts.find(x.from) == parts.find(y.from)) continue;
      const bool xy = y.to < 0 || findTurn(pg, x.from, y.to) >= 0;
      const bool yx = x.to < 0 || findTurn(pg, y.from, x.to) >= 0;
      if (!xy || !yx) continue;
      moveArc(pg, c, x.from, x.to, -1), moveArc(pg, c, y.from, y.to, -1);
      moveArc(pg, c, x.from, y.to, +1), moveArc(pg, c, y.from, x.to, +1);
      parts.unite(x.from, y.from);
      return true;
    }
  return false;
}

/// usedParts after every free swap at every junction.
Components mergedParts(const PlanGraph& pg, Circulation& c, std::vector<char>& used) {
  Components parts = usedParts(pg, c, used);
  std::vector<std::vector<int>> into(sz(pg.n));
  for (int e = 0; e < pg.m; ++e)
    if (used[sz(e)]) into[sz(pg.v[sz(e)])].push_back(e);
  for (int j = 0; j < pg.n; ++j)
    while (swapOnce(pg, c, into[sz(j)], parts)) {
    }
  return parts;
}

/// Shortest legal closed walk from edge c through some edge of the depot's part back to c,
/// trying c and the next few edges of c's part as the junction; empty when none exists.
std::vector<int> closedWalkToDepotPart(const PlanGraph& pg, const TurnPaths& paths, int c0,
                                       Components& parts, const std::vector<char>& used) {
  const int home = parts.find(pg.m), part = parts.find(c0);
  std::vector<int> best;
  double bestLength = std::numeric_limits<double>::infinity();
  for (int c = c0, tried = 0; c < pg.m && tried < 8; ++c) {
    if (!used[sz(c)] || parts.find(c) != part) continue;
    ++tried;
    const auto there =
        paths.toNearest(c, -1, [&](int e) { return used[sz(e)] && parts.find(e) == home; });
    if (!there) continue;
    const auto back = paths.toNearest(there->edges.back(), -1, [c](int e) { return e == c; });
    if (!back || there->length_m + back->length_m >= bestLength) continue;
    bestLength = there->length_m + back->length_m;
    best.assign(1, c);
    best.insert(best.end(), there->edges.begin(), there->edges.end());
    best.insert(best.end(), back->edges.begin(), back->edges.end());
  }
  return best;
}

/// The first used edge outside the depot's part, or -1.
int firstApart(const PlanGraph& pg, Components& parts, const std::vector<char>& used) {
  for (int e = 0; e < pg.m; ++e)
    if (used[sz(e)] && parts.find(e) != parts.find(pg.m)) return e;
  return -1;
}

/// Re-solves with the edges of a joining walk required too: the cheapest circulation then
/// often drives them as one trail with the rest (a closed walk added on top would drive the
/// depot's part twice). At most `rounds` re-solves; what stays apart is left to joinToDepot.
Circulation solveJoined(const PlanGraph& pg, const TurnPaths& paths, std::vector<char> required,
                        int depot, int rounds, int& solves) {
  Circulation c = cheapestCirculation(pg, required, depot);
  ++solves;
  for (int round = 0; round < rounds; ++round) {
    std::vector<char> used;
    Components parts = mergedParts(pg, c, used);
    const int apart = firstApart(pg, parts, used);
    if (apart < 0) break;
    const std::vector<int> walk = closedWalkToDepotPart(pg, paths, apart, parts, used);
    if (walk.empty()) break;
    for (int e : walk) required[sz(e)] = 1;
    c = cheapestCirculation(pg, required, depot);
    ++solves;
  }
  return c;
}

void joinToDepot(const PlanGraph& pg, const TurnPaths& paths, Circulation& c) {
  std::vector<char> used;
  Components parts = mergedParts(pg, c, used);
  for (int c0 = firstApart(pg, parts, used); c0 >= 0; c0 = firstApart(pg, parts, used)) {
    const std::vector<int> walk = closedWalkToDepotPart(pg, paths, c0, parts, used);
    if (walk.empty())
      throw std::runtime_error("rural postman: edge " + std::to_string(c0) +
                               " cannot be joined to the depot's round trip");
    for (std::size_t i = 1; i < walk.size(); ++i) {
      ++c.turn[sz(turnIndex(pg, walk[i - 1], walk[i]))];
      used[sz(walk[i])] = 1;
      parts.unite(pg.m, walk[i]);
    }
    parts.unite(pg.m, c0);
  }
}

/// Hierholzer on the used arcs from the depot vertex; returns the edges between the two visits
/// of the depot.
std::vector<int> eulerRoute(const PlanGraph& pg, Circulation c) {
  const int depotVertex = pg.m;
  std::vector<int> turnPtr(pg.next_off.begin(), pg.next_off.end() - 1);
  int leavePtr = 0;
  std::vector<int> stack{depotVertex}, circuit;
  while (!stack.empty()) {
    const int x = stack.back();
    int y = -1;
    if (x == depotVertex) {
      while (leavePtr < pg.m && c.leave[sz(leavePtr)] == 0) ++leavePtr;
      if (leavePtr < pg.m) --c.leave[sz(leavePtr)], y = leavePtr;
    } else {
      int& k = turnPtr[sz(x)];
      while (k < pg.nextEnd(x) && c.turn[sz(k)] == 0) ++k;
      if (k < pg.nextEnd(x))
        --c.turn[sz(k)], y = pg.next[sz(k)];
      else if (c.arrive[sz(x)] > 0)
        --c.arrive[sz(x)], y = depotVertex;
    }
    if (y >= 0)
      stack.push_back(y);
    else
      circuit.push_back(x), stack.pop_back();
  }
  for (int k : c.turn)
    if (k != 0) throw std::logic_error("rural postman: the Euler circuit left turns unused");
  // circuit is reversed and starts and ends with the depot vertex
  return std::vector<int>(circuit.rbegin() + 1, circuit.rend() - 1);
}

}  // namespace

std::vector<int> ruralPostmanRoute(const PlanGraph& pg, const TurnPaths& paths,
                                   const std::vector<char>& required, int depot, int* solves) {
  bool any = false;
  for (char r : required) any = any || r;
  if (!any) return {};
  int count = 0;
  Circulation c = solveJoined(pg, paths, required, depot, kJoinRounds, count);
  if (solves) *solves += count;
  joinToDepot(pg, paths, c);
  return eulerRoute(pg, std::move(c));
}

std::vector<double> distancesToNode(const PlanGraph& pg, int node) {
  std::vector<std::vector<int>> before(sz(pg.m));
  for (int e = 0; e < pg.m; ++e)
    for (int k = pg.nextBegin(e); k < pg.nextEnd(e); ++k) before[sz(pg.next[sz(k)])].push_back(e);
  std::vector<double> dist(sz(pg.m), std::numeric_limits<double>::infinity());
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
  for (int e = 0; e < pg.m; ++e)
    if (pg.v[sz(e)] == node) dist[sz(e)] = 0.0, queue.emplace(0.0, e);
  while (!queue.empty()) {
    const auto [d, f] = queue.top();
    queue.pop();
    if (d > dist[sz(f)]) continue;
    for (int e : before[sz(f)])
      if (d + pg.len[sz(f)] < dist[sz(e)]) {
        dist[sz(e)] = d + pg.len[sz(f)];
        queue.emplace(dist[sz(e)], e);
      }
  }
  return dist;
}

double routeLength(const PlanGraph& pg, const std::vector<int>& edges) {
  double l = 0.0;
  for (int e : edges) l += pg.len[sz(e)];
  return l;
}

}  // namespace slamroute::rl::fleet
