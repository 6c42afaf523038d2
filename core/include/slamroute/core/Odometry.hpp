#pragma once
// Wheel odometry + yaw-rate gyro of the mapping vehicle (what every survey car records next to
// its LiDAR; LeGO-LOAM takes an IMU the same way): forward speed and yaw rate over time, and the
// planar motion they integrate to between two times. File: a drive's odometry.csv.
#include <filesystem>
#include <vector>

#include "slamroute/core/Types.hpp"

namespace slamroute {

/// Speed and yaw rate, constant from t until the next sample's t.
struct OdometrySample {
  double t = 0.0;               ///< [s]
  double speed_mps = 0.0;       ///< forward speed [m/s]
  double yaw_rate_rad_s = 0.0;  ///< turn rate about the body z axis, counter-clockwise [rad/s]
};

class WheelOdometry {
 public:
  WheelOdometry() = default;
  /// Samples must be sorted by strictly increasing t and finite; throws otherwise.
  explicit WheelOdometry(std::vector<OdometrySample> samples);

  bool empty() const { return samples_.empty(); }
  const std::vector<OdometrySample>& samples() const { return samples_; }
  /// Planar motion from t0 to t1 in the body frame at t0 (x forward, yaw about z), integrated
  /// with the midpoint heading per piece; the first sample holds before it, the last after it.
  Pose3 motion(double t0, double t1) const;
  /// Yaw rate at t [rad/s] (0 when empty).
  double yawRate(double t) const;

 private:
  std::vector<OdometrySample> samples_;
};

/// CSV with header "t,speed_mps,yaw_rate_rad_s". Throws naming the file and line.
WheelOdometry readOdometryCsv(const std::filesystem::path& path);
void writeOdometryCsv(const std::filesystem::path& path, const WheelOdometry& odo);

}  // namespace slamroute
