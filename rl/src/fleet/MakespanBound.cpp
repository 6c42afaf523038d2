// A lower bound on the makespan of a fleet that counts every vehicle's trip from its depot.
//
// L1 / K ignores that each of the K vehicles drives out to its streets and back; with one depot
// at the edge of a city that is a large share of every route. The bound here is proven for any
// legal solution: K closed walks W_1..W_K, each from a depot back to a depot, every directed
// edge driven by at least one of them, makespan M = max |W_i|.
//
// Pick thresholds a, b >= 0 and call an edge e far when before(e) >= a and after(e) >= b
// (before: the shortest legal drive from a depot to where e may be taken next; after: the
// shortest legal drive from e's end back to a depot). F is the set of far edges, L(F) their
// summed length. Cut every walk W_i that drives a far edge at the start of its first far-edge
// traversal and at the end of its last one:
//  - the prefix is a legal drive from a depot to where that far edge is taken: >= a;
//  - the suffix is a legal drive from the end of a far edge to a depot: >= b;
//  - the middle holds every far-edge traversal of W_i.
// Every far edge is driven by some walk, inside that walk's middle, so the middles sum to at
// least L(F) and the longest of at most K middles is at least L(F) / K. Its walk is at least
// a + L(F) / K + b long, hence M >= a + b + L(F) / K for every (a, b) with F not empty (with
// no far edge no walk need go that far).
//
// For a fixed F the largest usable a and b are F's smallest before and after, so only the values
// the edges take are worth trying as thresholds. a = b = 0 gives (sum of edge lengths) / K; a
// far set of one edge gives less than that edge's round trip, which the planner keeps apart.
#include "MakespanBound.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace slamroute::rl::fleet {
namespace {

/// Thresholds for `a`: the distinct before values, at most max_count of them.
std::vector<double> beforeThresholds(const std::vector<EdgeReach>& edges, int max_count) {
  std::vector<double> values;
  for (const auto& e : edges) values.push_back(e.before_m);
  return spreadThresholds(std::move(values), max_count);
}

/// max over b of a + b + L(F) / k, F = {e : before >= a, after >= b} not empty (an empty F
/// proves nothing); `order`: by after, largest first. A threshold b counts only the edges whose
/// after is >= b, so it is taken after all edges of that after value are summed.
double bestForA(const std::vector<EdgeReach>& edges, const std::vector<std::size_t>& order,
                double a, int k) {
  double best = 0.0, far_len = 0.0;
  bool any_far = false;
  for (std::size_t i = 0; i < order.size(); ++i) {
    const EdgeReach& e = edges[order[i]];
    if (e.before_m >= a) far_len += e.len_m, any_far = true;
    const bool last_of_value = i + 1 == order.size() || edges[order[i + 1]].after_m < e.after_m;
    if (any_far && last_of_value && std::isfinite(e.after_m))
      best = std::max(best, a + e.after_m + far_len / k);
  }
  return best;
}

}  // namespace

std::vector<double> spreadThresholds(std::vector<double> values, int max_count) {
  values.erase(
      std::remove_if(values.begin(), values.end(), [](double v) { return !std::isfinite(v); }),
      values.end());
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  if (static_cast<int>(values.size()) <= max_count) return values;
  std::vector<double> picked;
  const double step = static_cast<double>(values.size() - 1) / (max_count - 1);
  for (int i = 0; i < max_count; ++i)
    picked.push_back(values[static_cast<std::size_t>(std::lround(i * step))]);
  return picked;
}

std::vector<EdgeReach> edgeReaches(const FleetContext& ctx) {
  std::vector<EdgeReach> out;
  for (int e = 0; e < ctx.pg.m; ++e) {
    const auto i = static_cast<std::size_t>(e);
    EdgeReach r{ctx.pg.len[i], std::numeric_limits<double>::infinity(),
                std::numeric_limits<double>::infinity()};
    for (int v = 0; v < ctx.vehicles(); ++v) {
      const auto vi = static_cast<std::size_t>(v);
      r.before_m = std::min(r.before_m, ctx.from_depot[vi][i] - r.len_m);
      r.after_m = std::min(r.after_m, ctx.to_depot[vi][i]);
    }
    out.push_back(r);
  }
  return out;
}

double depotTripsBound(const std::vector<EdgeReach>& edges, int vehicles, int max_thresholds) {
  if (edges.empty() || vehicles < 1) return 0.0;
  std::vector<std::size_t> order(edges.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(),
            [&](std::size_t x, std::size_t y) { return edges[x].after_m > edges[y].after_m; });
  double best = 0.0;
  for (double a : beforeThresholds(edges, std::max(2, max_thresholds)))
    best = std::max(best, bestForA(edges, order, a, vehicles));
  return best;
}

}  // namespace slamroute::rl::fleet
