// Streets where survey vehicles set off (paper §3.1 step 2, a case the paper leaves open).
//
// A covering route that starts on a street leaves no trace through the junction at its start.
// When no other vehicle drove straight on into that street, the junction shows only the vehicles
// that turn there: the hollow cylinder sees two branches (a bend), the street through the bend
// has no node, and the street the route set off on starts at a dead end a few metres beside the
// bend, which no turn enters (default city seed 3: R3C3_R2C3). A dead end whose tip lies within
// bend_end_reach_m of another street's centreline (at least clear_radius_m from its ends), where
// that street bends (its legs clear_radius_m either side meet at less than 150 degrees) and one
// leg runs on within 30 degrees of the dead end's street continued past its tip, is a junction
// at the bend: a node there splits the bent street and the dead end's street ends at it. Where a
// street runs straight past, or the dead end's street does not line up with a leg, it stays a
// dead end (StopLineEnds.cpp handles a street that runs straight at another).
#include <cmath>
#include <limits>
#include <optional>

#include "Streets.hpp"

namespace slamroute::roadgraph::detail {
namespace {

/// The nearest centreline point to `tip` within `reach` (2D, within half_h in height) on a
/// street other than `self`, at least `margin` from both of its ends.
std::optional<PointOnStreet> nearestStreetPoint(const std::vector<Street>& streets,
                                                std::size_t self, const Point3& tip, double reach,
                                                double margin, double half_h) {
  std::optional<PointOnStreet> best;
  double best_d = reach;
  for (std::size_t k = 0; k < streets.size(); ++k) {
    const Polyline& c = streets[k].centre;
    if (k == self || streets[k].comp < 0 || c.size() < 2) continue;
    const double len = polylineLength(c);
    double s = 0.0;
    for (std::size_t i = 0; i + 1 < c.size(); s += (c[i + 1] - c[i]).norm(), ++i) {
      const Vec3 e = c[i + 1] - c[i];
      const double l2 = e.squaredNorm();
      const double u = l2 > 1e-12 ? std::clamp((tip - c[i]).dot(e) / l2, 0.0, 1.0) : 0.0;
      const Point3 at = c[i] + u * e;
      const double d = (at - tip).head<2>().norm();
      const double arc = s + u * std::sqrt(l2);
      if (d > best_d || std::abs(at.z() - tip.z()) > half_h || arc < margin || arc > len - margin)
        continue;
      best_d = d;
      best = PointOnStreet{k, arc, at};
    }
  }
  return best;
}

Eigen::Vector2d headingTo(const Point3& from, const Point3& to) {
  const Eigen::Vector2d d = (to - from).head<2>();
  return d.norm() > 1e-6 ? Eigen::Vector2d(d.normalized()) : Eigen::Vector2d::Zero();
}

/// Whether the street bends at `x` with one leg running on along `dir`.
bool bendLinesUp(const Street& s, const PointOnStreet& x, const Eigen::Vector2d& dir,
                 double leg_m) {
  const double max_cos = std::cos(30.0 * M_PI / 180.0);
  const Eigen::Vector2d back = headingTo(x.at, pointAtArc(s.centre, x.arc - leg_m));
  const Eigen::Vector2d fwd = headingTo(x.at, pointAtArc(s.centre, x.arc + leg_m));
  if (back.isZero() || fwd.isZero() || back.dot(fwd) <= -max_cos) return false;  // straight
  return back.dot(dir) >= max_cos || fwd.dot(dir) >= max_cos;
}

}  // namespace

void joinBendEnds(GraphNodes& gn, std::vector<Street>& streets, const StreetPoints& spts,
                  const EdgeConfig& ec, double half_h, GraphBuildStats& st) {
  if (ec.bend_end_reach_m <= 0.0) return;
  const int joined =
      joinDeadEnds(gn, streets, spts, ec.clear_radius_m,
                   [&](std::size_t k, const Point3& tip,
                       const Eigen::Vector2d& dir) -> std::optional<PointOnStreet> {
                     const auto x = nearestStreetPoint(streets, k, tip, ec.bend_end_reach_m,
                                                       ec.clear_radius_m, half_h);
                     if (!x || !bendLinesUp(streets[x->street], *x, dir, ec.clear_radius_m))
                       return std::nullopt;
                     return x;
                   });
  st.dead_ends -= static_cast<std::size_t>(joined);
  st.bend_end_junctions += static_cast<std::size_t>(joined);
}

}  // namespace slamroute::roadgraph::detail
