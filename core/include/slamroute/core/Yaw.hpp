#pragma once
// The heading of a rotation, for the places that compare or integrate headings.
#include <cmath>

#include "slamroute/core/Types.hpp"

namespace slamroute {

/// Heading of a rotation about the world z axis: the angle of its x axis in the x-y plane
/// (radians, (-pi, pi]).
inline double yawOf(const Mat3& R) { return std::atan2(R(1, 0), R(0, 0)); }
inline double yawOf(const Pose3& T) { return yawOf(Mat3(T.linear())); }

}  // namespace slamroute
