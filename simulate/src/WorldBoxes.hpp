#pragma once
// Internal: analytic ray / oriented-box intersection for the moving traffic boxes.
#include <cmath>
#include <vector>

#include "slamroute/core/Types.hpp"
#include "slamroute/simulate/Traffic.hpp"

namespace slamroute::simulate::detail {

/// A vehicle box prepared for ray tests: centre, length/width axes in the xy plane, half extents.
struct PreparedBox {
  Eigen::Vector3d c;     ///< box centre (not bottom) [m]
  Eigen::Vector2d u, v;  ///< unit length axis, unit width axis
  Eigen::Vector3d half;  ///< half length, half width, half height
};

inline PreparedBox prepareBox(const VehicleBox& b) {
  PreparedBox p;
  const double h = b.heading_deg * M_PI / 180.0;
  p.u = Eigen::Vector2d(std::cos(h), std::sin(h));
  p.v = Eigen::Vector2d(-p.u.y(), p.u.x());
  p.c = Eigen::Vector3d(b.x, b.y, b.z + b.height / 2);
  p.half = Eigen::Vector3d(b.length / 2, b.width / 2, b.height / 2);
  return p;
}

/// Slab test in the box frame. Returns true and sets t (< tmax) and the world normal (facing
/// the origin) on a hit in front of the origin (origin inside the box: no hit).
inline bool intersectBox(const PreparedBox& b, const Eigen::Vector3d& org,
                         const Eigen::Vector3d& dir, double tmax, double* t,
                         Eigen::Vector3d* normal) {
  const Eigen::Vector3d r = org - b.c;
  const double o[3] = {b.u.dot(r.head<2>()), b.v.dot(r.head<2>()), r.z()};
  const double d[3] = {b.u.dot(dir.head<2>()), b.v.dot(dir.head<2>()), dir.z()};
  double t0 = 0.0, t1 = tmax;
  int axis = -1;
  double sign = 0;
  for (int k = 0; k < 3; ++k) {
    if (std::abs(d[k]) < 1e-12) {
      if (std::abs(o[k]) > b.half[k]) return false;
      continue;
    }
    double ta = (-b.half[k] - o[k]) / d[k], tb = (b.half[k] - o[k]) / d[k];
    double s = -1;  // entering through the -half face when d > 0
    if (ta > tb) {
      std::swap(ta, tb);
      s = 1;
    }
    if (ta > t0) {
      t0 = ta;
      axis = k;
      sign = s;
    }
    t1 = std::min(t1, tb);
    if (t0 > t1) return false;
  }
  if (axis < 0) return false;  // origin inside
  *t = t0;
  Eigen::Vector3d n;
  if (axis == 0)
    n << b.u * sign, 0;
  else if (axis == 1)
    n << b.v * sign, 0;
  else
    n << 0, 0, sign;
  *normal = n;
  return true;
}

}  // namespace slamroute::simulate::detail
