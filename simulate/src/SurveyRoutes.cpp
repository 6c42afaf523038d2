// coveringRoutes: a greedy set of drivable routes that together visit (nearly) every edge.
// Covering routes rather than random trips alone: random trips leave short side
// streets and dead ends unvisited for a long time, so survey vehicles drive covering routes and
// random background traffic adds the remaining variety.
#include <limits>
#include <queue>

#include "slamroute/core/DriveGraph.hpp"
#include "slamroute/simulate/Survey.hpp"

namespace slamroute::simulate {
namespace {

/// Shortest path (over the turn graph, cost = length of the edges entered) from edge `from` to
/// the nearest edge with covered == false; the path excludes `from`. Empty when none reachable.
std::vector<std::size_t> pathToNearestUncovered(const DriveGraph& g, std::size_t from,
                                                const std::vector<bool>& covered) {
  const std::size_t n = g.numEdges();
  std::vector<double> dist(n, std::numeric_limits<double>::infinity());
  std::vector<std::size_t> prev(n, n);
  using Item = std::pair<double, std::size_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> pq;
  dist[from] = 0.0;
  pq.push({0.0, from});
  while (!pq.empty()) {
    const auto [d, e] = pq.top();
    pq.pop();
    if (d > dist[e]) continue;
    if (e != from && !covered[e]) {
      std::vector<std::size_t> path;
      for (std::size_t x = e; x != from; x = prev[x]) path.push_back(x);
      return {path.rbegin(), path.rend()};
    }
    for (std::size_t next : g.allowed_next[e]) {
      const double nd = d + g.edges[next].length_m;
      if (nd < dist[next]) {
        dist[next] = nd;
        prev[next] = e;
        pq.push({nd, next});
      }
    }
  }
  return {};
}

}  // namespace

std::vector<std::vector<std::size_t>> coveringRoutes(const DriveGraph& g, double max_length_m) {
  const std::size_t n = g.numEdges();
  std::vector<bool> covered(n, false);
  std::vector<bool> has_pred(n, false);
  for (std::size_t e = 0; e < n; ++e)
    for (std::size_t next : g.allowed_next[e]) has_pred[next] = true;

  std::vector<std::vector<std::size_t>> routes;
  auto nextStart = [&]() -> std::size_t {
    for (std::size_t e = 0; e < n; ++e)
      if (!covered[e] && !has_pred[e]) return e;  // nothing leads here: must start here
    for (std::size_t e = 0; e < n; ++e)
      if (!covered[e]) return e;
    return n;
  };
  for (std::size_t start = nextStart(); start < n; start = nextStart()) {
    std::vector<std::size_t> route{start};
    covered[start] = true;
    double len = g.edges[start].length_m;
    while (len < max_length_m) {
      const auto path = pathToNearestUncovered(g, route.back(), covered);
      if (path.empty()) break;
      for (std::size_t e : path) {
        covered[e] = true;
        len += g.edges[e].length_m;
        route.push_back(e);
      }
    }
    routes.push_back(std::move(route));
  }
  return routes;
}

}  // namespace slamroute::simulate
