#pragma once
// The online pose estimate an explorer maps with when `explore.map_poses` is `slam`: wheel
// odometry + gyro dead reckoning, the same error model a drive records (simulate's
// OdometryNoise), integrated step by step from the true start pose. Its drift is the error a
// vehicle without a prior map carries into the shared grid.
#include <cstdint>
#include <optional>

#include "slamroute/core/Types.hpp"
#include "slamroute/simulate/DriveConfig.hpp"
#include "slamroute/simulate/OdometryNoise.hpp"

namespace slamroute::explore {

class DeadReckoning {
 public:
  DeadReckoning(const simulate::DriveConfig& drive, std::uint64_t seed) : noise_(drive, seed) {}
  /// Called every simulation step with the sensor's true pose at t: the odometry reading of the
  /// motion since the previous call is integrated (midpoint heading). The first call anchors
  /// the estimate at the truth.
  void step(double t, const Pose3& truth);
  /// The estimate of a sensor truly at `truth` (the pose of the latest step): the truth moved by
  /// the planar error (position and heading) accumulated so far.
  Pose3 estimate(const Pose3& truth) const;

 private:
  simulate::OdometryNoise noise_;
  std::optional<Pose3> last_truth_;
  double last_t_ = 0.0;
  double x_m_ = 0.0, y_m_ = 0.0, yaw_rad_ = 0.0;  ///< estimated planar pose
};

}  // namespace slamroute::explore
