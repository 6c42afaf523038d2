#pragma once
// The range of plausible coordinates in every file slamroute reads (nets, traces, graphs,
// trajectories). They are metres in a local frame (netconvert subtracts the net offset); beyond
// 10,000 km a value is no place on Earth, and squares, grids and sums of such values overflow.
#include <cmath>

namespace slamroute {

inline constexpr double kMaxCoordinateM = 1e7;
inline constexpr const char* kCoordinateRule = "coordinates must be finite and within 10,000 km";

inline bool plausibleCoordinate(double v) {
  return std::isfinite(v) && std::abs(v) <= kMaxCoordinateM;
}

}  // namespace slamroute
