// `tsp`: a tour over all nodes with shortest legal path distances (paper Table 3's comparison).
// Exact Held-Karp up to tsp.exact_max_nodes; above, a heuristic tour labelled as such:
// Christofides (LEMON) on the symmetrised distances improved by 2-opt (LEMON), or, above
// tsp.christofides_max_nodes (its O(n^3) matching), a greedy tour + 2-opt. The orientation with
// the lower directed cost is kept. Legs are expanded from the actual arrival edge, so the route
// obeys turn permissions even where node-to-node distances could not.
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "Index.hpp"
#include "LemonTsp.hpp"
#include "slamroute/core/Log.hpp"
#include "slamroute/rl/Planners.hpp"

namespace slamroute::rl {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

using Matrix = std::vector<std::vector<double>>;

Matrix nodeDistances(const PlanGraph& pg, const TurnPaths& paths) {
  Matrix d(sz(pg.n), std::vector<double>(sz(pg.n), kInf));
  for (int i = 0; i < pg.n; ++i) {
    const std::vector<double> de = paths.distances(-1, i);
    d[sz(i)][sz(i)] = 0.0;
    for (int e = 0; e < pg.m; ++e) {
      double& x = d[sz(i)][sz(pg.v[sz(e)])];
      if (pg.v[sz(e)] != i) x = std::min(x, de[sz(e)]);
    }
  }
  return d;
}

double tourCost(const Matrix& d, const std::vector<int>& t, bool closed) {
  double c = 0.0;
  for (std::size_t k = 1; k < t.size(); ++k) c += d[sz(t[k - 1])][sz(t[k])];
  if (closed && t.size() > 1) c += d[sz(t.back())][sz(t.front())];
  return c;
}

std::vector<int> orientTour(const Matrix& d, std::vector<int> tour, int start, bool closed) {
  const auto it = std::find(tour.begin(), tour.end(), start);
  std::rotate(tour.begin(), it, tour.end());
  std::vector<int> rev(tour);
  std::reverse(rev.begin() + 1, rev.end());
  return tourCost(d, rev, closed) < tourCost(d, tour, closed) ? rev : tour;
}

/// Drives the tour: from the edge actually arrived on (turn permissions), the shortest legal leg
/// to each node not yet passed. The node-to-node matrix measures legs from a standing start at a
/// node, free to leave by any edge; arriving by a given edge may forbid the U-turn or the turn
/// that leg began with, so a leg can be much longer than its matrix entry. Nodes an earlier leg
/// drove through are skipped (the goal is every node visited). Returns the route length [m].
double expandLegs(const PlanGraph& pg, const TurnPaths& paths, const std::vector<int>& order,
                  int start, std::vector<int>& edges) {
  std::vector<char> seen(sz(pg.n), 0);
  seen[sz(start)] = 1;
  int cur_edge = -1, cur_node = start;
  double length = 0.0;
  for (std::size_t k = 1; k < order.size(); ++k) {
    const int target = order[k];
    const bool home = k + 1 == order.size() && target == start;
    if (target == cur_node || (seen[sz(target)] && !home)) continue;
    auto leg = paths.toNearest(cur_edge, cur_node, [&](int e) { return pg.v[sz(e)] == target; });
    if (!leg) throw std::runtime_error("tsp: node " + std::to_string(target) + " unreachable");
    for (int e : leg->edges) seen[sz(pg.v[sz(e)])] = 1;
    edges.insert(edges.end(), leg->edges.begin(), leg->edges.end());
    length += leg->length_m;
    cur_edge = edges.back();
    cur_node = target;
  }
  return length;
}

}  // namespace

std::vector<int> heldKarp(const Matrix& d, int start, bool closed, double* cost) {
  const int n = static_cast<int>(d.size());
  if (n > 22) throw std::invalid_argument("heldKarp: " + std::to_string(n) + " nodes is too many");
  if (n == 0) return {};
  if (n == 1) {
    if (cost) *cost = 0.0;
    return {start};
  }
  // Others: the n-1 nodes other than start, bit b <-> others[b].
  std::vector<int> others;
  for (int i = 0; i < n; ++i)
    if (i != start) others.push_back(i);
  const int k = n - 1;
  const std::size_t full = (std::size_t{1} << k);
  // dp[S][j]: cheapest path from start visiting exactly S (bits), ending at others[j] in S.
  std::vector<double> dp(full * sz(k), kInf);
  std::vector<signed char> parent(full * sz(k), -1);
  for (int j = 0; j < k; ++j)
    dp[(std::size_t{1} << j) * sz(k) + sz(j)] = d[sz(start)][sz(others[sz(j)])];
  for (std::size_t S = 1; S < full; ++S)
    for (int j = 0; j < k; ++j) {
      if (!(S >> j & 1)) continue;
      const double base = dp[S * sz(k) + sz(j)];
      if (base == kInf) continue;
      for (int nx = 0; nx < k; ++nx) {
        if (S >> nx & 1) continue;
        const std::size_t S2 = S | (std::size_t{1} << nx);
        const double c = base + d[sz(others[sz(j)])][sz(others[sz(nx)])];
        if (c < dp[S2 * sz(k) + sz(nx)]) {
          dp[S2 * sz(k) + sz(nx)] = c;
          parent[S2 * sz(k) + sz(nx)] = static_cast<signed char>(j);
        }
      }
    }
  double best = kInf;
  int last = -1;
  for (int j = 0; j < k; ++j) {
    const double c =
        dp[(full - 1) * sz(k) + sz(j)] + (closed ? d[sz(others[sz(j)])][sz(start)] : 0.0);
    if (c < best) best = c, last = j;
  }
  if (last < 0) throw std::invalid_argument("heldKarp: some node cannot be reached");
  std::vector<int> order;
  std::size_t S = full - 1;
  for (int j = last; j >= 0;) {
    order.push_back(others[sz(j)]);
    const int pj = parent[S * sz(k) + sz(j)];
    S &= ~(std::size_t{1} << j);
    j = pj;
  }
  order.push_back(start);
  std::reverse(order.begin(), order.end());
  if (cost) *cost = best;
  return order;
}

PlanOutput planTsp(const PlanGraph& pg, const TurnPaths& paths, const Config& cfg, int start) {
  const TspConfig& tc = cfg.tsp;
  if (pg.n > tc.max_nodes)
    throw std::invalid_argument(
        "tsp: " + std::to_string(pg.n) +
        " nodes is above rl.tsp.max_nodes = " + std::to_string(tc.max_nodes) +
        " (its n^2 distance matrix); use --planner postman or raise the limit");
  const Matrix d = nodeDistances(pg, paths);
  PlanOutput out;
  std::vector<int> order;
  std::string method;
  if (pg.n <= std::min(tc.exact_max_nodes, 22)) {
    order = heldKarp(d, start, tc.closed_tour);
    method = "held-karp";
  } else {
    const bool chris = pg.n <= tc.christofides_max_nodes;
    method = chris ? "christofides+2opt" : "greedy+2opt";
    logWarn("tsp: " + std::to_string(pg.n) +
            " nodes is above the exact limit rl.tsp.exact_max_nodes = " +
            std::to_string(tc.exact_max_nodes) + "; using a heuristic tour (" + method + ")");
    order = detail::lemonTour(d, chris);
    order = orientTour(d, order, start, tc.closed_tour);
    out.heuristic = true;
    out.notes = "tsp: heuristic tour (" + method + "), not guaranteed optimal";
  }
  const double matrix_cost = tourCost(d, order, tc.closed_tour);
  if (tc.closed_tour) order.push_back(start);
  const double length = expandLegs(pg, paths, order, start, out.edges);
  out.stats = TspStats{method, length, matrix_cost};
  return out;
}

}  // namespace slamroute::rl
