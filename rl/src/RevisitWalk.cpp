// Coverage walk with loop-closure revisits (see RevisitWalk.hpp).
#include "RevisitWalk.hpp"

#include <algorithm>
#include <limits>

#include "Index.hpp"

namespace slamroute::rl::detail {

namespace {

class Walker {
 public:
  explicit Walker(const CoverageProblem& p)
      : p_(p), t_(p.pg, p.eif, p.start, p.motions), covered_(sz(p.pg.m), 0) {}

  void driveTo(int target, bool revisit) {
    path_.clear();
    p_.dist.appendPath(cur_, target, path_);
    for (int e : path_) {
      const double c = t_.drive(e);
      covered_[sz(e)] = 1;
      r_.edges.push_back(e);
      r_.c_m2.push_back(c);
      r_.length_m += p_.pg.len[sz(e)];
      if (revisit) r_.revisit_length_m += p_.pg.len[sz(e)];
      r_.max_c_m2 = std::max(r_.max_c_m2, c);
      r_.excess_m2 += std::max(0.0, c - p_.c_threshold_m2);
    }
    if (!path_.empty()) cur_ = target;
  }
  int nextUncovered(int j) {
    const auto& cities = p_.cities;
    while (next_ < static_cast<int>(cities.size()) &&
           (next_ <= j || covered_[sz(cities[sz(next_)])]))
      ++next_;
    return next_ < static_cast<int>(cities.size()) ? cities[sz(next_)] : -1;
  }
  bool covered(int e) const { return covered_[sz(e)] != 0; }
  int cur() const { return cur_; }
  const UncertaintyTracker& tracker() const { return t_; }
  WalkResult& result() { return r_; }

 private:
  const CoverageProblem& p_;
  UncertaintyTracker t_;
  std::vector<char> covered_;
  std::vector<int> path_;
  int cur_ = -1, next_ = 0;
  WalkResult r_;
};

/// Max C_k over driving from the tracker's state along `from` -> `to` (no-op when to < 0).
double simulateLeg(const CoverageProblem& p, UncertaintyTracker& t, int from, int to,
                   std::vector<int>& buf) {
  double mx = t.c();
  if (to < 0) return mx;
  buf.clear();
  p.dist.appendPath(from, to, buf);
  for (int e : buf) mx = std::max(mx, t.drive(e));
  return mx;
}

}  // namespace

int nearestRevisit(const CoverageProblem& p, const UncertaintyTracker& t, int cur, int after) {
  const PlanGraph& pg = p.pg;
  const int here = cur >= 0 ? pg.v[sz(cur)] : p.start;
  int best = -1;
  double best_cost = std::numeric_limits<double>::infinity();
  for (int f = 0; f < pg.m; ++f) {
    const int w = pg.v[sz(f)];
    if (w == here || !t.mapped(w) || t.placeC(w) > p.place_max_c_m2 || t.placeC(w) >= t.c())
      continue;
    const double to = p.dist.d(cur, f);
    if (t.sinceVisitM(w) + to < p.eif.loop_min_travel_m) continue;
    const double back = after >= 0 ? p.dist.d(f, after) : 0.0;
    if (to + back < best_cost) best_cost = to + back, best = f;
  }
  return best;
}

WalkResult walkCoverage(const CoverageProblem& p, const RevisitPolicy& policy) {
  Walker w(p);
  const int n = static_cast<int>(p.cities.size());
  for (int j = 0; j < n; ++j) {
    const int city = p.cities[sz(j)];
    if (w.covered(city)) continue;
    w.driveTo(city, false);
    w.result().reached.push_back(j);
    WalkState s;
    s.j = j;
    s.cur = w.cur();
    const int next = w.nextUncovered(j);
    s.last = next < 0;
    s.after = next >= 0 ? next : (p.closed ? p.dist.returnEdge(s.cur) : -1);
    const int f = policy(s, w.tracker());
    if (f < 0) continue;
    w.driveTo(f, true);
    w.result().revisit_after.push_back(j);
  }
  if (p.closed) {
    const int f = p.dist.returnEdge(w.cur());
    if (f >= 0) w.driveTo(f, false);
  }
  return std::move(w.result());
}

/// Max C_k when the walk goes from `cur` (after an optional revisit to `revisit`) to `after`
/// and then takes the nearest revisit from there (none when `last`).
double lookahead(const CoverageProblem& p, const UncertaintyTracker& t, const WalkState& s,
                 int revisit, std::vector<int>& buf) {
  UncertaintyTracker ahead = t;
  int from = s.cur;
  double mx = t.c();
  if (revisit >= 0) {
    mx = std::max(mx, simulateLeg(p, ahead, from, revisit, buf));
    from = revisit;
  }
  mx = std::max(mx, simulateLeg(p, ahead, from, s.after, buf));
  if (!s.last)
    mx = std::max(mx, simulateLeg(p, ahead, s.after, nearestRevisit(p, ahead, s.after, -1), buf));
  return mx;
}

WalkResult walkSwitching(const CoverageProblem& p, std::vector<int>& considered) {
  considered.assign(p.cities.size(), -1);
  std::vector<int> buf;
  auto policy = [&](const WalkState& s, const UncertaintyTracker& t) {
    const int now = nearestRevisit(p, t, s.cur, s.after);
    considered[sz(s.j)] = now;
    if (now < 0 || s.after < 0) return -1;
    // Revisit now when going on and revisiting only at the next city would break the bound, and
    // revisiting now keeps it. Where no revisit can keep it (the next city too far from any
    // place mapped with little uncertainty) the walk goes on: revisiting would only shuttle.
    if (lookahead(p, t, s, -1, buf) <= p.c_threshold_m2) return -1;
    return lookahead(p, t, s, now, buf) <= p.c_threshold_m2 ? now : -1;
  };
  return walkCoverage(p, policy);
}

}  // namespace slamroute::rl::detail
