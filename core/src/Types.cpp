#include "slamroute/core/Types.hpp"

#include <cmath>

namespace slamroute {

double polylineLength(const Polyline& pl) {
  double len = 0.0;
  for (std::size_t i = 1; i < pl.size(); ++i) len += (pl[i] - pl[i - 1]).norm();
  return len;
}

double yawOf(const Mat3& R) { return std::atan2(R(1, 0), R(0, 0)); }

double yawOf(const Pose3& T) { return yawOf(Mat3(T.linear())); }

}  // namespace slamroute
