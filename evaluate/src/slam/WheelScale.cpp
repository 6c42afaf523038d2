#include "WheelScale.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "RecentMedian.hpp"

namespace slamroute::evaluate::slam {

void WheelScale::observe(double wheel_m, double lidar_m) {
  const OdometryConfig& c = cfg_;
  if (!(c.wheel_scale_stretch_m > 0) || !(wheel_m > 0) || !std::isfinite(lidar_m)) return;
  wheel_sum_m_ += wheel_m;
  lidar_sum_m_ += lidar_m;
  if (wheel_sum_m_ < c.wheel_scale_stretch_m) return;
  const std::optional<double> r = pushRecentMedian(
      ratios_, lidar_sum_m_ / wheel_sum_m_, c.wheel_scale_stretches, c.wheel_scale_min_stretches);
  wheel_sum_m_ = lidar_sum_m_ = 0.0;
  if (r) scale_ = std::clamp(*r, 1.0 - c.wheel_scale_max, 1.0 + c.wheel_scale_max);
}

}  // namespace slamroute::evaluate::slam
