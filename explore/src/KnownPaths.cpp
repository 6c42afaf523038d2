// KnownPaths: Dijkstra on the line graph restricted to known edges.
#include "slamroute/explore/KnownPaths.hpp"

#include <algorithm>
#include <functional>
#include <limits>
#include <queue>
#include <utility>

namespace slamroute::explore {

KnownPaths::KnownPaths(const rl::PlanGraph& pg, int from, const std::function<bool(int)>& known)
    : pg_(pg), from_(from) {
  const double inf = std::numeric_limits<double>::infinity();
  dist_.assign(static_cast<std::size_t>(pg.m), inf);
  pred_.assign(static_cast<std::size_t>(pg.m), -1);
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> q;
  auto relax = [&](int e, double d, int pred) {
    if (!known(e) || d >= dist_[static_cast<std::size_t>(e)]) return;
    dist_[static_cast<std::size_t>(e)] = d;
    pred_[static_cast<std::size_t>(e)] = pred;
    q.push({d, e});
  };
  for (int k = pg.nextBegin(from); k < pg.nextEnd(from); ++k) {
    const int f = pg.next[static_cast<std::size_t>(k)];
    relax(f, pg.len[static_cast<std::size_t>(f)], -1);
  }
  while (!q.empty()) {
    const auto [d, e] = q.top();
    q.pop();
    if (d > dist_[static_cast<std::size_t>(e)]) continue;
    for (int k = pg.nextBegin(e); k < pg.nextEnd(e); ++k) {
      const int f = pg.next[static_cast<std::size_t>(k)];
      relax(f, d + pg.len[static_cast<std::size_t>(f)], e);
    }
  }
}

std::optional<KnownPath> KnownPaths::pathTo(int edge) const {
  if (dist_[static_cast<std::size_t>(edge)] == std::numeric_limits<double>::infinity())
    return std::nullopt;
  KnownPath p;
  p.length_m = dist_[static_cast<std::size_t>(edge)];
  for (int e = edge; e != -1; e = pred_[static_cast<std::size_t>(e)]) p.edges.push_back(e);
  std::reverse(p.edges.begin(), p.edges.end());
  return p;
}

std::optional<int> KnownPaths::nearest(const std::function<bool(int)>& goal) const {
  std::optional<int> best;
  for (int e = 0; e < pg_.m; ++e)
    if (goal(e) && dist_[static_cast<std::size_t>(e)] < std::numeric_limits<double>::infinity() &&
        (!best || dist_[static_cast<std::size_t>(e)] < dist_[static_cast<std::size_t>(*best)]))
      best = e;
  return best;
}

}  // namespace slamroute::explore
