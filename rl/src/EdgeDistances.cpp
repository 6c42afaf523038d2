// All-pairs legal distances between edge states (see EdgeDistances.hpp).
#include "EdgeDistances.hpp"

#include <algorithm>
#include <limits>

#include "Index.hpp"

namespace slamroute::rl::detail {

EdgeDistances::EdgeDistances(const PlanGraph& pg, const TurnPaths& paths, int start)
    : pg_(&pg), m_(pg.m), start_(start) {
  dist_.resize(sz(m_ + 1) * sz(m_));
  pred_.resize(dist_.size());
  std::vector<double> dist;
  std::vector<int> pred;
  for (int src = 0; src <= m_; ++src) {
    paths.run(src < m_ ? src : -1, start, dist, pred);
    const std::size_t base = sz(src) * sz(m_);
    for (int f = 0; f < m_; ++f) {
      dist_[base + sz(f)] = static_cast<float>(dist[sz(f)]);
      const int p = pred[sz(f)];
      pred_[base + sz(f)] = p >= 0 && p < m_ ? p : -1;  // node-state source -> -1
    }
  }
  for (int e = 0; e < m_; ++e)
    if (pg.v[sz(e)] == start) into_start_.push_back(e);
}

void EdgeDistances::appendPath(int from, int to, std::vector<int>& out) const {
  if (from == to) return;
  const std::size_t base = row(from);
  const std::size_t first = out.size();
  for (int x = to; x >= 0 && x != from; x = pred_[base + sz(x)]) out.push_back(x);
  std::reverse(out.begin() + static_cast<std::ptrdiff_t>(first), out.end());
}

int EdgeDistances::returnEdge(int from) const {
  if (from >= 0 && pg_->v[sz(from)] == start_) return -1;
  int best = -1;
  float best_d = std::numeric_limits<float>::infinity();
  for (int f : into_start_)
    if (d(from, f) < best_d) best_d = d(from, f), best = f;
  return best;
}

}  // namespace slamroute::rl::detail
