// coveringRoutes: a greedy set of drivable routes that together visit (nearly) every edge and
// drive through every bend.
// Covering routes rather than random trips alone: random trips leave short side
// streets and dead ends unvisited for a long time, so survey vehicles drive covering routes and
// random background traffic adds the remaining variety.
// Edges alone are not enough for the graph built from the traces: at a junction with two arms
// (a bend or corner) a cover may reach each outgoing edge by a U-turn, so no trace passes
// round the bend, the traces on either side end there and the street is cut in two dead ends.
// At a turning place (a corner where a two-way street meets a one-way street, so one direction
// of the two-way street can only turn round there) too: the road graph gives it a node where
// the traces turn round.
#include <limits>
#include <queue>
#include <set>

#include "slamroute/core/DriveGraph.hpp"
#include "slamroute/simulate/Survey.hpp"

namespace slamroute::simulate {
namespace {

/// What a cover still has to drive: edges, and turns (edge e -> allowed_next[e][j]).
struct CoverState {
  std::vector<bool> edge_done;
  std::vector<std::vector<bool>> turn_done;  ///< parallel to allowed_next; true when not needed

  void drive(std::size_t from, std::size_t to, const DriveGraph& g) {
    edge_done[to] = true;
    const auto& next = g.allowed_next[from];
    for (std::size_t j = 0; j < next.size(); ++j)
      if (next[j] == to) turn_done[from][j] = true;
  }
  bool edgeOrTurnLeft(std::size_t e) const {
    if (!edge_done[e]) return true;
    for (bool done : turn_done[e])
      if (!done) return true;
    return false;
  }
};

/// Vertices with exactly two neighbouring vertices (over in- and out-edges).
std::vector<bool> twoArmVertices(const DriveGraph& g) {
  std::vector<std::set<std::size_t>> arms(g.numVertices());
  for (const auto& e : g.edges) {
    if (e.u == e.v) continue;
    arms[e.u].insert(e.v);
    arms[e.v].insert(e.u);
  }
  std::vector<bool> two(arms.size());
  for (std::size_t v = 0; v < arms.size(); ++v) two[v] = arms[v].size() == 2;
  return two;
}

bool isUTurn(const DriveGraph& g, std::size_t e, std::size_t next) {
  return g.edges[next].v == g.edges[e].u;
}

/// Nothing driven yet; the turns to drive are those round a bend: through a two-arm junction,
/// not a U-turn.
CoverState initialState(const DriveGraph& g) {
  const auto two_arm = twoArmVertices(g);
  CoverState s{std::vector<bool>(g.numEdges(), false), {}};
  s.turn_done.resize(g.numEdges());
  for (std::size_t e = 0; e < g.numEdges(); ++e) {
    const bool bend = two_arm[g.edges[e].v];
    for (std::size_t next : g.allowed_next[e])
      s.turn_done[e].push_back(!bend || isUTurn(g, e, next));
  }
  return s;
}

/// Shortest path (over the turn graph, cost = length of the edges entered) from edge `from` to
/// the nearest edge not yet driven or through the nearest turn not yet driven; the path excludes
/// `from`. Empty when none reachable. Search items >= n are turns: n + the position of the turn
/// in a flat list, so a turn is reached at the cost of the edge it leads onto.
std::vector<std::size_t> pathToNearestLeft(const DriveGraph& g, std::size_t from,
                                           const CoverState& s) {
  const std::size_t n = g.numEdges();
  std::vector<double> dist(n, std::numeric_limits<double>::infinity());
  std::vector<std::size_t> prev(n, n);
  std::vector<std::pair<std::size_t, std::size_t>> turns;  // (from edge, to edge) queued
  using Item = std::pair<double, std::size_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> pq;
  auto pathTo = [&](std::size_t e) {
    std::vector<std::size_t> path;
    for (std::size_t x = e; x != from; x = prev[x]) path.push_back(x);
    return std::vector<std::size_t>(path.rbegin(), path.rend());
  };
  dist[from] = 0.0;
  pq.push({0.0, from});
  while (!pq.empty()) {
    const auto [d, item] = pq.top();
    pq.pop();
    if (item >= n) {
      const auto [e, next] = turns[item - n];
      auto path = pathTo(e);
      path.push_back(next);
      return path;
    }
    if (d > dist[item]) continue;
    if (item != from && !s.edge_done[item]) return pathTo(item);
    const auto& nexts = g.allowed_next[item];
    for (std::size_t j = 0; j < nexts.size(); ++j) {
      const std::size_t next = nexts[j];
      const double nd = d + g.edges[next].length_m;
      if (!s.turn_done[item][j]) {
        turns.emplace_back(item, next);
        pq.push({nd, n + turns.size() - 1});
      }
      if (nd < dist[next]) {
        dist[next] = nd;
        prev[next] = item;
        pq.push({nd, next});
      }
    }
  }
  return {};
}

/// Where the next route starts: an edge not yet driven that nothing leads to, else any edge not
/// yet driven, else an edge with a turn left to drive; n when the cover is complete.
std::size_t nextStart(const DriveGraph& g, const CoverState& s, const std::vector<bool>& has_pred) {
  const std::size_t n = g.numEdges();
  for (std::size_t e = 0; e < n; ++e)
    if (!s.edge_done[e] && !has_pred[e]) return e;  // nothing leads here: must start here
  for (std::size_t e = 0; e < n; ++e)
    if (!s.edge_done[e]) return e;
  for (std::size_t e = 0; e < n; ++e)
    if (s.edgeOrTurnLeft(e)) return e;
  return n;
}

}  // namespace

std::vector<std::vector<std::size_t>> coveringRoutes(const DriveGraph& g, double max_length_m) {
  const std::size_t n = g.numEdges();
  CoverState s = initialState(g);
  std::vector<bool> has_pred(n, false);
  for (std::size_t e = 0; e < n; ++e)
    for (std::size_t next : g.allowed_next[e]) has_pred[next] = true;

  std::vector<std::vector<std::size_t>> routes;
  for (std::size_t start = nextStart(g, s, has_pred); start < n;
       start = nextStart(g, s, has_pred)) {
    // A route started for a turn alone drives at least to that turn, however long its edge.
    bool progressed = !s.edge_done[start];
    std::vector<std::size_t> route{start};
    s.edge_done[start] = true;
    double len = g.edges[start].length_m;
    while (len < max_length_m || !progressed) {
      const auto path = pathToNearestLeft(g, route.back(), s);
      if (path.empty()) break;
      for (std::size_t e : path) {
        s.drive(route.back(), e, g);
        len += g.edges[e].length_m;
        route.push_back(e);
      }
      progressed = true;
    }
    routes.push_back(std::move(route));
  }
  return routes;
}

}  // namespace slamroute::simulate
