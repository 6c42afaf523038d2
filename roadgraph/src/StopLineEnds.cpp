// Side arms that end at a stop line (paper §3.1 step 2, a case the paper leaves open).
//
// A vehicle whose route ends on a side street leaves the traces at the stop line, 5-8 m short of
// the street it would turn into. When only such vehicles drove the arm, its points never touch
// the crossing street, the hollow cylinder sees two branches there and the arm dead-ends beside
// a street that runs past without a node. A dead end whose street runs straight at another
// street (its last stop_line_reach_m, continued, crosses that street's centreline at more than
// 30 degrees, and the crossed street goes on at least clear_radius_m either side, as it would
// past a junction the cylinder finds) is that T junction: a node at the crossing splits the
// crossed street in two and the side street ends there. A dead end near a street's end (a corner
// no vehicle drove round) is left to the end merge (EndNodes.cpp), which runs first.
#include <cmath>
#include <optional>

#include "Streets.hpp"

namespace slamroute::roadgraph::detail {
namespace {

/// The nearest crossing of the ray tip + t * dir (0 <= t <= reach) with the centreline of a
/// street other than `self` at more than 30 degrees, at least `margin` from both of its ends.
std::optional<PointOnStreet> rayCrossing(const std::vector<Street>& streets, std::size_t self,
                                         const Point3& tip, const Eigen::Vector2d& dir,
                                         double reach, double margin, double half_h) {
  std::optional<PointOnStreet> best;
  double best_t = reach;
  const double max_cos = std::cos(30.0 * M_PI / 180.0);
  for (std::size_t k = 0; k < streets.size(); ++k) {
    const Polyline& c = streets[k].centre;
    if (k == self || streets[k].comp < 0 || c.size() < 2) continue;
    const double len = polylineLength(c);
    double s = 0.0;
    for (std::size_t i = 0; i + 1 < c.size(); s += (c[i + 1] - c[i]).norm(), ++i) {
      const Eigen::Vector2d p = c[i].head<2>(), e = (c[i + 1] - c[i]).head<2>();
      const double den = dir.x() * e.y() - dir.y() * e.x();
      if (e.norm() < 1e-9 || std::abs(den) < 1e-9) continue;
      if (std::abs(dir.dot(e.normalized())) > max_cos) continue;
      const Eigen::Vector2d w = p - tip.head<2>();
      const double t = (w.x() * e.y() - w.y() * e.x()) / den;      // along the ray
      const double u = (w.x() * dir.y() - w.y() * dir.x()) / den;  // along the segment
      if (t < 0.0 || t > best_t || u < 0.0 || u > 1.0) continue;
      const Point3 at = c[i] + u * (c[i + 1] - c[i]);
      const double arc = s + u * (c[i + 1] - c[i]).norm();
      if (std::abs(at.z() - tip.z()) > half_h || arc < margin || arc > len - margin) continue;
      best_t = t;
      best = PointOnStreet{k, arc, at};
    }
  }
  return best;
}

}  // namespace

void joinStopLineEnds(GraphNodes& gn, std::vector<Street>& streets, const StreetPoints& spts,
                      const EdgeConfig& ec, double half_h, GraphBuildStats& st) {
  if (ec.stop_line_reach_m <= 0.0) return;
  const int joined = joinDeadEnds(
      gn, streets, spts, ec.stop_line_reach_m,
      [&](std::size_t k, const Point3& tip, const Eigen::Vector2d& dir) {
        return rayCrossing(streets, k, tip, dir, ec.stop_line_reach_m, ec.clear_radius_m, half_h);
      });
  st.dead_ends -= static_cast<std::size_t>(joined);
  st.stop_line_junctions += static_cast<std::size_t>(joined);
}

}  // namespace slamroute::roadgraph::detail
