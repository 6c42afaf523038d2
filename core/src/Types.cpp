#include "slamroute/core/Types.hpp"

namespace slamroute {

double polylineLength(const Polyline& pl) {
  double len = 0.0;
  for (std::size_t i = 1; i < pl.size(); ++i) len += (pl[i] - pl[i - 1]).norm();
  return len;
}

}  // namespace slamroute
