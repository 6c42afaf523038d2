// A lower bound on the makespan that also counts the detours a vehicle needs between its far
// streets (one-way streets and forbidden turns make a set of streets expensive to drive in a
// few trails), by min-cost flow on the turn-expanded graph.
//
// Any legal solution: K closed walks W_1..W_K from a depot back to a depot, every directed edge
// driven, makespan M = max |W_i|. Pick a set F of edges ("far"). Cut each walk that drives an
// edge of F at the start of its first F traversal and at the end of its last one: prefix,
// middle, suffix. Let r be the number of such walks (1 <= r <= K). For each of them
//  - the prefix is a legal drive from a depot to where its first F edge e is taken:
//    >= before(e);
//  - the suffix is a legal drive from the end of its last F edge f back to a depot: >= after(f);
//  - the middle is a legal walk that starts by driving e and ends by driving f.
// On the turn-expanded graph (vertices in[e], out[e] per edge, arcs in[e] -> out[e] of cost
// len(e) and out[e] -> in[g] for each allowed turn e -> g) add a source S with arcs S -> in[e]
// of cost before(e) for e in F, a sink T with arcs out[f] -> T of cost after(f) for f in F, and
// an arc T -> S carrying exactly r units. The r cut walks, each as S -> its middle -> T, form an
// integral circulation in which every drive arc of F carries at least one unit, and its cost is
// the walks' summed length. So sum_i |W_i| >= C_F(r), the cheapest such circulation, and
// M >= C_F(r) / r >= min over r in 1..K of C_F(r) / r. Costs are rounded down to whole
// millimetres, which only lowers C_F(r).
//
// With S and T costs replaced by the thresholds a <= before, b <= after this is at least the
// depot-trips bound a + b + L(F) / K (MakespanBound.cpp); it adds the deadheading F needs.
#include <lemon/network_simplex.h>
#include <lemon/smart_graph.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "MakespanBound.hpp"

namespace slamroute::rl::fleet {
namespace {

std::size_t sz(int i) { return static_cast<std::size_t>(i); }
long long floorMm(double metres) { return static_cast<long long>(std::floor(metres * 1000.0)); }

using G = lemon::SmartDigraph;
using Simplex = lemon::NetworkSimplex<G, long long, long long>;

/// The turn-expanded graph with S and T for one far set; `r` is set per solve.
class FarFlow {
 public:
  FarFlow(const PlanGraph& pg, const std::vector<EdgeReach>& reach, const std::vector<char>& far)
      : lower_(g_), upper_(g_), cost_(g_) {
    std::vector<G::Node> in(sz(pg.m)), out(sz(pg.m));
    for (int e = 0; e < pg.m; ++e) in[sz(e)] = g_.addNode(), out[sz(e)] = g_.addNode();
    const G::Node s = g_.addNode(), t = g_.addNode();
    const long long many = 4LL * pg.m + 4;  // no edge needs more traversals than this
    const auto arc = [&](G::Node a, G::Node b, long long lo, long long cost) {
      const G::Arc x = g_.addArc(a, b);
      lower_.set(x, lo), upper_.set(x, many), cost_.set(x, cost);
      return x;
    };
    for (int e = 0; e < pg.m; ++e) {
      arc(in[sz(e)], out[sz(e)], far[sz(e)] ? 1 : 0, floorMm(pg.len[sz(e)]));
      for (int k = pg.nextBegin(e); k < pg.nextEnd(e); ++k)
        arc(out[sz(e)], in[sz(pg.next[sz(k)])], 0, 0);
      if (!far[sz(e)]) continue;
      arc(s, in[sz(e)], 0, floorMm(reach[sz(e)].before_m));
      arc(out[sz(e)], t, 0, floorMm(reach[sz(e)].after_m));
    }
    back_ = arc(t, s, 1, 0);
  }

  /// C_F(r) [m], +inf when no circulation exists.
  double cheapest(int r) {
    lower_.set(back_, r), upper_.set(back_, r);
    Simplex ns(g_);
    ns.lowerMap(lower_).upperMap(upper_).costMap(cost_);
    if (ns.run() != Simplex::OPTIMAL) return std::numeric_limits<double>::infinity();
    return static_cast<double>(ns.totalCost()) / 1000.0;
  }

 private:
  G g_;
  G::ArcMap<long long> lower_, upper_, cost_;
  G::Arc back_;
};

/// min over r in 1..k of C_F(r) / r. C_F is convex in r (a min-cost flow's cost in its amount),
/// so C_F(r) / r falls and then rises: r C_F(r+1) - (r+1) C_F(r), the sign of its step, grows
/// with r by (r+1)(C_F(r+2) - 2 C_F(r+1) + C_F(r)) >= 0. Bisection on that sign finds the
/// minimum in about 2 log2(k) flows, so a large fleet costs little more than a small one.
double boundForSet(const PlanGraph& pg, const std::vector<EdgeReach>& reach,
                   const std::vector<char>& far, int k) {
  FarFlow flow(pg, reach, far);
  std::map<int, double> per_walk;
  const auto at = [&](int r) {
    auto it = per_walk.find(r);
    if (it == per_walk.end()) it = per_walk.emplace(r, flow.cheapest(r) / r).first;
    return it->second;
  };
  int lo = 1, hi = k;
  while (lo < hi) {
    const int mid = lo + (hi - lo) / 2;
    if (at(mid + 1) < at(mid))
      lo = mid + 1;
    else
      hi = mid;
  }
  const double best = at(lo);
  return std::isfinite(best) ? best : 0.0;
}

/// Round-trip thresholds that define the far sets: the distinct values of
/// before + len + after, at most max_sets of them.
std::vector<double> roundTripThresholds(const std::vector<EdgeReach>& reach, int max_sets) {
  std::vector<double> values;
  for (const auto& e : reach) values.push_back(e.before_m + e.len_m + e.after_m);
  return spreadThresholds(std::move(values), max_sets);
}

}  // namespace

double farFlowBound(const PlanGraph& pg, const std::vector<EdgeReach>& reach, int vehicles,
                    int max_sets) {
  if (reach.empty() || vehicles < 1) return 0.0;
  double best = 0.0;
  for (double threshold : roundTripThresholds(reach, std::max(2, max_sets))) {
    std::vector<char> far(reach.size(), 0);
    for (std::size_t e = 0; e < reach.size(); ++e) {
      const double rt = reach[e].before_m + reach[e].len_m + reach[e].after_m;
      far[e] = std::isfinite(rt) && rt >= threshold;
    }
    best = std::max(best, boundForSet(pg, reach, far, vehicles));
  }
  return best;
}

}  // namespace slamroute::rl::fleet
