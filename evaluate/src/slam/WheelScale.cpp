#include "WheelScale.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace slamroute::evaluate::slam {

void WheelScale::observe(double wheel_m, double lidar_m) {
  const OdometryConfig& c = cfg_;
  if (!(c.wheel_scale_stretch_m > 0) || !(wheel_m > 0) || !std::isfinite(lidar_m)) return;
  wheel_sum_m_ += wheel_m;
  lidar_sum_m_ += lidar_m;
  if (wheel_sum_m_ < c.wheel_scale_stretch_m) return;
  ratios_.push_back(lidar_sum_m_ / wheel_sum_m_);
  wheel_sum_m_ = lidar_sum_m_ = 0.0;
  if (static_cast<int>(ratios_.size()) > c.wheel_scale_stretches) ratios_.pop_front();
  if (static_cast<int>(ratios_.size()) < c.wheel_scale_min_stretches) return;
  std::vector<double> r(ratios_.begin(), ratios_.end());
  std::nth_element(r.begin(), r.begin() + static_cast<long>(r.size() / 2), r.end());
  scale_ = std::clamp(r[r.size() / 2], 1.0 - c.wheel_scale_max, 1.0 + c.wheel_scale_max);
}

}  // namespace slamroute::evaluate::slam
