// Turning places (a case paper §3.1 leaves open): a bend where a two-way street meets a one-way
// street. The hollow cylinder sees two branches there, so there is no node, and once vehicles
// drive round the bend its points make one street through it. But one direction of the two-way
// street can only be entered (or only be left) by turning round at the bend: as a direction of
// the street through the bend it would become a graph edge that no turn enters or leaves, as a
// street cannot turn round part-way, and a planner could not drive it. The traces show where
// vehicles turn round: a run along a street that advances at least min_run_m, reverses and goes
// back at least min_run_m, at least clear_radius_m from both ends of the street's points (a U-turn
// at a junction or a dead end happens at its node). Where min_direction_runs runs turned round
// within clear_radius_m of each other, a node (kTurningPlace, not an intersection) splits the
// street, and the U-turn is a turn at that node (allowed by SumoTurns.cpp where SUMO allows it).
#include <algorithm>

#include "Streets.hpp"

namespace slamroute::roadgraph::detail {
namespace {

/// Where run k_first..k_last (positions in `order`) turns round along centreline `c`: the arc
/// position of its far or near extreme when it advances and comes back `need` either side of it,
/// else -1.
double turnRoundArc(const Traces& traces, const std::vector<std::size_t>& order,
                    std::size_t k_first, std::size_t k_last, const Polyline& c, double need) {
  std::vector<double> a;
  for (std::size_t k = k_first; k <= k_last; ++k)
    a.push_back(arcPosition(c, traces.points[order[k]].pos));
  const auto far = std::max_element(a.begin(), a.end());
  const auto near = std::min_element(a.begin(), a.end());
  if (*far - *std::min_element(a.begin(), far + 1) >= need &&
      *far - *std::min_element(far, a.end()) >= need)
    return *far;
  if (*std::max_element(a.begin(), near + 1) - *near >= need &&
      *std::max_element(near, a.end()) - *near >= need)
    return *near;
  return -1.0;
}

/// Per street, the arc positions along its centreline where runs turned round part-way.
std::vector<std::vector<double>> turnRoundArcs(const std::vector<Street>& streets,
                                               const Traces& traces,
                                               const std::vector<std::size_t>& order,
                                               const std::vector<int>& street_of_point,
                                               const EdgeConfig& ec) {
  std::vector<std::vector<double>> arcs(streets.size());
  forEachRun(traces, order, street_of_point, ec.max_gap_s,
             [&](int s, std::size_t k_first, std::size_t k_last) {
               const Street& street = streets[static_cast<std::size_t>(s)];
               if (street.comp < 0) return;  // a short link has no points of its own
               const double len = polylineLength(street.centre);
               const double a =
                   turnRoundArc(traces, order, k_first, k_last, street.centre, ec.min_run_m);
               if (a >= ec.clear_radius_m && a <= len - ec.clear_radius_m)
                 arcs[static_cast<std::size_t>(s)].push_back(a);
             });
  return arcs;
}

/// The places along one street: groups of turn-round positions with gaps of at most
/// clear_radius_m, of at least min_direction_runs runs each, at their median; far end first.
std::vector<double> placesAlong(std::vector<double> arcs, const EdgeConfig& ec) {
  std::sort(arcs.begin(), arcs.end());
  std::vector<double> places;
  for (std::size_t i = 0; i < arcs.size();) {
    std::size_t j = i + 1;
    while (j < arcs.size() && arcs[j] - arcs[j - 1] <= ec.clear_radius_m) ++j;
    if (static_cast<int>(j - i) >= ec.min_direction_runs) places.push_back(arcs[(i + j) / 2]);
    i = j;
  }
  std::reverse(places.begin(), places.end());
  return places;
}

Point3 pointAtArc(const Polyline& c, double arc) {
  double s = 0.0;
  for (std::size_t i = 0; i + 1 < c.size(); ++i) {
    const double len = (c[i + 1] - c[i]).norm();
    if (s + len >= arc && len > 1e-9) return c[i] + (c[i + 1] - c[i]) * ((arc - s) / len);
    s += len;
  }
  return c.back();
}

}  // namespace

void splitAtTurningPlaces(GraphNodes& gn, std::vector<Street>& streets, const StreetPoints& spts,
                          const Traces& traces, const std::vector<std::size_t>& order,
                          const std::vector<int>& street_of_point, const EdgeConfig& ec,
                          GraphBuildStats& st) {
  const auto arcs = turnRoundArcs(streets, traces, order, street_of_point, ec);
  for (std::size_t k = 0; k < arcs.size(); ++k)
    for (const double arc : placesAlong(arcs[k], ec)) {  // far end first: arcs of k stay valid
      gn.pos.push_back(pointAtArc(streets[k].centre, arc));
      gn.is_end.push_back(kTurningPlace);
      splitStreet(streets, k, arc, static_cast<int>(gn.pos.size()) - 1, spts.pts);
      ++st.turning_places;
    }
}

}  // namespace slamroute::roadgraph::detail
