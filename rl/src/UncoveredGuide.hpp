#pragma once
// Private helper of Q-learning: the action that leads toward the nearest uncovered part of the
// graph by the shortest legal path (Dijkstra over edge states, stopped at the first uncovered
// edge). Coverage only grows while a path is followed, so a path to the nearest uncovered edge
// stays a shortest path to the nearest one from every state on it while its target is still
// uncovered (a nearer one from a later state would have been nearer from the source too): the
// path is kept and followed, and searched again only when the state leaves it or its target
// gets covered. Most steps thus cost O(1); a search explores only the ball up to the target.
#include <algorithm>
#include <utility>
#include <vector>

#include "Index.hpp"
#include "slamroute/rl/PlanGraph.hpp"

namespace slamroute::rl::detail {

class UncoveredGuide {
 public:
  explicit UncoveredGuide(const PlanGraph& pg)
      : pg_(pg),
        dist_(sz(pg.m), 0.0),
        pred_(sz(pg.m), -1),
        seen_(sz(pg.m), 0),
        along_(sz(pg.m + pg.n), -1),
        along_stamp_(sz(pg.m + pg.n), 0) {}

  /// Forgets the kept path: coverage was reset (a new episode).
  void reset() { target_ = -1; }

  /// The edge to drive from state s (edge state e < m, node state m + i) toward the nearest edge
  /// with is_new(edge) true; -1 when nothing uncovered is reachable.
  template <class IsNew>
  int toward(int s, const IsNew& is_new) {
    if (target_ >= 0 && is_new(target_) && along_stamp_[sz(s)] == path_stamp_) return along_[sz(s)];
    target_ = search(s, is_new);
    if (target_ < 0) return -1;
    keepPath(s);
    return along_[sz(s)];
  }

 private:
  /// Actions of state s: the edges allowed after edge s, or the edges leaving node s - m.
  std::pair<int, int> actions(int s) const {
    if (s < pg_.m) return {pg_.nextBegin(s), pg_.nextEnd(s)};
    return {pg_.outBegin(s - pg_.m), pg_.outEnd(s - pg_.m)};
  }
  int action(int s, int k) const { return s < pg_.m ? pg_.next[sz(k)] : pg_.out[sz(k)]; }

  /// Dijkstra from state s; the nearest edge with is_new true (-1: none). pred_ links the path.
  template <class IsNew>
  int search(int s, const IsNew& is_new) {
    ++stamp_;
    heap_.clear();
    auto relax = [this](int from, int e, double d) {
      if (seen_[sz(e)] == stamp_ && dist_[sz(e)] <= d) return;
      seen_[sz(e)] = stamp_, dist_[sz(e)] = d, pred_[sz(e)] = from;
      heap_.emplace_back(-d, e);
      std::push_heap(heap_.begin(), heap_.end());
    };
    const auto [b, end] = actions(s);
    for (int k = b; k < end; ++k) relax(s, action(s, k), pg_.len[sz(action(s, k))]);
    while (!heap_.empty()) {
      std::pop_heap(heap_.begin(), heap_.end());
      const auto [neg_d, e] = heap_.back();
      heap_.pop_back();
      if (-neg_d > dist_[sz(e)]) continue;  // a stale entry
      if (is_new(e)) return e;
      for (int k = pg_.nextBegin(e); k < pg_.nextEnd(e); ++k)
        relax(e, pg_.next[sz(k)], -neg_d + pg_.len[sz(pg_.next[sz(k)])]);
    }
    return -1;
  }

  /// Records, for each state on the path from s to target_, the edge driven next.
  void keepPath(int s) {
    ++path_stamp_;
    for (int e = target_;;) {
      const int from = pred_[sz(e)];
      along_[sz(from)] = e;
      along_stamp_[sz(from)] = path_stamp_;
      if (from == s) break;
      e = from;
    }
  }

  const PlanGraph& pg_;
  std::vector<double> dist_;
  std::vector<int> pred_, seen_;
  std::vector<std::pair<double, int>> heap_;
  std::vector<int> along_, along_stamp_;  // per state: the path's next edge, valid at path_stamp_
  int stamp_ = 0, path_stamp_ = 0, target_ = -1;
};

}  // namespace slamroute::rl::detail
