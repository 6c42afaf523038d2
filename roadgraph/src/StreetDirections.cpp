// Direction(s) of travel of every street (paper §3.1 step 2, "a street driven only one way is
// one-way"): each vehicle's consecutive points on a street form a run; a run that advances more
// than min_run_m along the centreline counts for that direction (and a run can count for both:
// a vehicle that drives into a dead end and turns round there travels it both ways). A street
// with runs in one direction only is one-way; with both, or with no usable run, two-way
// (GraphBuilder.cpp). On streets shorter than 2 x (clear_radius_m + min_run_m) drives from one
// end node to the other count as runs too, and short links take the directions vehicles drove
// them (ShortLinks.cpp).
#include <algorithm>
#include <cmath>
#include <limits>

#include "Streets.hpp"

namespace slamroute::roadgraph::detail {

void forEachRun(const Traces& traces, const std::vector<std::size_t>& order,
                const std::vector<int>& street_of_point, double max_gap_s,
                const std::function<void(int, std::size_t, std::size_t)>& fn) {
  std::size_t run_first = 0;
  for (std::size_t k = 1; k <= order.size(); ++k) {
    const std::size_t prev = order[k - 1];
    const bool breaks = k == order.size() ||
                        traces.points[order[k]].vehicle != traces.points[prev].vehicle ||
                        traces.points[order[k]].t - traces.points[prev].t > max_gap_s ||
                        street_of_point[order[k]] != street_of_point[prev];
    if (!breaks) continue;
    if (street_of_point[prev] >= 0 && run_first < k - 1)
      fn(street_of_point[prev], run_first, k - 1);
    run_first = k;
  }
}

TravelCounts countDirections(const Traces& traces, const std::vector<std::size_t>& order,
                             const std::vector<int>& street_of_point,
                             const std::vector<Street>& streets, const std::vector<Polyline>& polys,
                             const Passages& passages, const EdgeConfig& ec) {
  std::vector<int> fwd(streets.size(), 0), bwd(streets.size(), 0);
  for (std::size_t k = 0; k < streets.size(); ++k)
    if (streets[k].comp < 0) {
      fwd[k] = streets[k].link_fwd >= ec.min_link_vehicles ? ec.min_direction_runs : 0;
      bwd[k] = streets[k].link_bwd >= ec.min_link_vehicles ? ec.min_direction_runs : 0;
    }
  // A street's points start clear_radius_m from its nodes, so on a street shorter than about
  // 2 x (clear_radius_m + min_run_m) few runs progress min_run_m: drives from one of its nodes to
  // the other over its points count too.
  for (const auto& [key, vehicles] : passages) {
    const auto [from, to, k] = key;
    if (k < 0 || vehicles < ec.min_link_vehicles) continue;
    const Street& s = streets[static_cast<std::size_t>(k)];
    if (polylineLength(polys[static_cast<std::size_t>(k)]) >=
        2 * (ec.clear_radius_m + ec.min_run_m))
      continue;
    if (from == s.u && to == s.v) fwd[static_cast<std::size_t>(k)] += vehicles;
    if (from == s.v && to == s.u) bwd[static_cast<std::size_t>(k)] += vehicles;
  }
  // A run counts in each direction it progresses along the street by `need`: a vehicle that
  // drives into a dead end and turns round there travels it both ways in one run.
  auto closeRun = [&](int s, std::size_t k_first, std::size_t k_last) {
    const auto& pl = polys[static_cast<std::size_t>(s)];
    const double len = polylineLength(pl);
    const double need = std::min(ec.min_run_m, 0.4 * len);
    double lo = std::numeric_limits<double>::infinity(), hi = -lo, rise = 0.0, fall = 0.0;
    for (std::size_t k = k_first; k <= k_last; ++k) {
      const double a = arcPosition(pl, traces.points[order[k]].pos);
      lo = std::min(lo, a);
      hi = std::max(hi, a);
      rise = std::max(rise, a - lo);
      fall = std::max(fall, hi - a);
    }
    if (rise > need) ++fwd[static_cast<std::size_t>(s)];
    if (fall > need) ++bwd[static_cast<std::size_t>(s)];
  };
  forEachRun(traces, order, street_of_point, ec.max_gap_s, closeRun);
  return {std::move(fwd), std::move(bwd)};
}

}  // namespace slamroute::roadgraph::detail
