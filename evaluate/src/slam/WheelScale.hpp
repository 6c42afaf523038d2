#pragma once
// The wheel odometry's scale, measured by the LiDAR. A car's wheel speed reads a few per cent
// off (tyre radius, pressure, load); where the scan-to-map holds the motion along the street
// the ratio of registered to wheel distance tells by how much, and the prediction across a
// stretch the LiDAR cannot measure (a bridge between uniform parapets) then follows the wheels
// at their true scale. The ratio is taken per stretch of road and the scale is the median of
// the recent stretches: a stretch where the registration slid along the street is an outlier,
// not a shift of the estimate.
#include <deque>

#include "slamroute/evaluate/Config.hpp"

namespace slamroute::evaluate::slam {

class WheelScale {
 public:
  explicit WheelScale(const OdometryConfig& cfg) : cfg_(cfg) {}

  /// One registered step: `wheel_m` by the (unscaled) wheels, `lidar_m` by the registration.
  void observe(double wheel_m, double lidar_m);
  /// The factor for the wheels' distances: 1 until enough road was measured.
  double scale() const { return scale_; }

 private:
  const OdometryConfig& cfg_;
  double wheel_sum_m_ = 0.0;  ///< the stretch being measured
  double lidar_sum_m_ = 0.0;
  std::deque<double> ratios_;  ///< the recent stretches' lidar / wheel
  double scale_ = 1.0;
};

}  // namespace slamroute::evaluate::slam
