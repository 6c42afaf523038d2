// Turning places (a case paper §3.1 leaves open): a bend where a two-way street meets a one-way
// street. The hollow cylinder sees two branches there, so there is no node, and once vehicles
// drive round the bend its points make one street through it. But one direction of the two-way
// street can only be entered (or only be left) by turning round at the bend: as a direction of
// the street through the bend it would become a graph edge that no turn enters or leaves, as a
// street cannot turn round part-way, and a planner could not drive it. The traces show where
// vehicles turn round: a run along a street that advances at least min_run_m, reverses and goes
// back at least min_run_m, at least clear_radius_m from both ends of the street's points (a U-turn
// at a junction or a dead end happens at its node). Where min_direction_runs runs turned round
// within clear_radius_m of each other and the street is two-way on one side and one-way on the
// other (where it goes on two-way, every direction is reached without the U-turn), a node
// (kTurningPlace, not an intersection) splits the street, and the U-turn is a turn at that node
// (allowed by SumoTurns.cpp where SUMO allows it).
#include <algorithm>

#include "Streets.hpp"

namespace slamroute::roadgraph::detail {
namespace {

/// Where a run (its arc positions along the centreline, in time order) turns round: its far or
/// near extreme when it advances and comes back `need` either side of it, else -1.
double turnRoundArc(const std::vector<double>& a, double need) {
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

/// Per street, where its runs turned round part-way (arc positions along its centreline), and
/// each run's arc positions.
struct StreetRuns {
  std::vector<double> turns;
  std::vector<std::vector<double>> arcs;
};

std::vector<StreetRuns> streetRuns(const std::vector<Street>& streets, const Traces& traces,
                                   const std::vector<std::size_t>& order,
                                   const std::vector<int>& street_of_point, const EdgeConfig& ec) {
  std::vector<StreetRuns> out(streets.size());
  forEachRun(
      traces, order, street_of_point, ec.max_gap_s,
      [&](int s, std::size_t k_first, std::size_t k_last) {
        const Street& street = streets[static_cast<std::size_t>(s)];
        if (street.comp < 0) return;  // a short link has no points of its own
        StreetRuns& r = out[static_cast<std::size_t>(s)];
        std::vector<double> a;
        for (std::size_t k = k_first; k <= k_last; ++k)
          a.push_back(arcPosition(street.centre, traces.points[order[k]].pos));
        const double turn = turnRoundArc(a, ec.min_run_m);
        if (turn >= ec.clear_radius_m && turn <= polylineLength(street.centre) - ec.clear_radius_m)
          r.turns.push_back(turn);
        r.arcs.push_back(std::move(a));
      });
  return out;
}

/// The directions in which runs advance `need` within arc positions [lo, hi]: bit 1 u -> v,
/// bit 2 v -> u.
int directionsWithin(const StreetRuns& r, double lo, double hi, double need) {
  int dirs = 0;
  for (const auto& a : r.arcs) {
    double low = hi, high = lo, rise = 0.0, fall = 0.0;
    for (double x : a) {
      x = std::clamp(x, lo, hi);
      low = std::min(low, x);
      high = std::max(high, x);
      rise = std::max(rise, x - low);
      fall = std::max(fall, high - x);
    }
    dirs |= (rise >= need ? 1 : 0) | (fall >= need ? 2 : 0);
  }
  return dirs;
}

/// A turning place: the street is two-way on one side of `arc` and one-way on the other, so the
/// direction that ends there is entered or left only by turning round. Where vehicles turn
/// round on a street that goes on two-way (or on a divided road's two carriageways), every
/// direction is reached without the U-turn.
bool directionEndsAt(const StreetRuns& r, double arc, double length_m, double need) {
  const int head = directionsWithin(r, 0.0, arc, need);
  const int tail = directionsWithin(r, arc, length_m, need);
  return (head == 3 && (tail == 1 || tail == 2)) || (tail == 3 && (head == 1 || head == 2));
}

/// The places along one street: groups of turn-round positions with gaps of at most
/// clear_radius_m, of at least min_direction_runs runs each, at their median, where a direction
/// ends; far end first.
std::vector<double> placesAlong(const StreetRuns& r, double length_m, const EdgeConfig& ec) {
  std::vector<double> arcs = r.turns;
  std::sort(arcs.begin(), arcs.end());
  std::vector<double> places;
  for (std::size_t i = 0; i < arcs.size();) {
    std::size_t j = i + 1;
    while (j < arcs.size() && arcs[j] - arcs[j - 1] <= ec.clear_radius_m) ++j;
    const double arc = arcs[(i + j) / 2];
    if (static_cast<int>(j - i) >= ec.min_direction_runs &&
        directionEndsAt(r, arc, length_m, ec.min_run_m))
      places.push_back(arc);
    i = j;
  }
  std::reverse(places.begin(), places.end());
  return places;
}

}  // namespace

void splitAtTurningPlaces(GraphNodes& gn, std::vector<Street>& streets, const StreetPoints& spts,
                          const Traces& traces, const std::vector<std::size_t>& order,
                          const std::vector<int>& street_of_point, const EdgeConfig& ec,
                          GraphBuildStats& st) {
  const auto runs = streetRuns(streets, traces, order, street_of_point, ec);
  for (std::size_t k = 0; k < runs.size(); ++k)
    for (const double arc : placesAlong(runs[k], polylineLength(streets[k].centre), ec)) {
      // far end first: the arc positions on the part kept at k stay valid
      gn.pos.push_back(pointAtArc(streets[k].centre, arc));
      gn.is_end.push_back(kTurningPlace);
      splitStreet(streets, k, arc, static_cast<int>(gn.pos.size()) - 1, spts.pts);
      ++st.turning_places;
    }
}

}  // namespace slamroute::roadgraph::detail
