#pragma once
// Wheel odometry + IMU of the mapping vehicle (what every survey car records next to its LiDAR;
// LeGO-LOAM takes an IMU the same way): forward speed and yaw rate over time, the planar motion
// they integrate to between two times, and optionally the IMU's absolute roll and pitch (from
// gravity). File: a drive's odometry.csv.
#include <filesystem>
#include <optional>
#include <vector>

#include <cmath>
#include <limits>

#include "slamroute/core/Types.hpp"

namespace slamroute {

/// Speed and yaw rate, constant from t until the next sample's t.
struct OdometrySample {
  double t = 0.0;               ///< [s]
  double speed_mps = 0.0;       ///< forward speed [m/s]
  double yaw_rate_rad_s = 0.0;  ///< turn rate about the body z axis, counter-clockwise [rad/s]
  /// Absolute roll and pitch of the body (Z-Y-X Euler angles, i.e. independent of the heading) as
  /// an IMU levels them against gravity; NaN when not recorded [rad].
  double roll_rad = std::numeric_limits<double>::quiet_NaN();
  double pitch_rad = std::numeric_limits<double>::quiet_NaN();
  bool hasAttitude() const { return std::isfinite(roll_rad) && std::isfinite(pitch_rad); }
};

/// Roll and pitch of the IMU [rad].
struct Attitude {
  double roll_rad = 0.0;
  double pitch_rad = 0.0;
};

/// Z-Y-X Euler roll and pitch of a rotation (independent of its heading).
Attitude attitudeOf(const Mat3& R);

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
  /// Roll and pitch of the sample in force at t, when the samples have them.
  std::optional<Attitude> attitude(double t) const;

 private:
  /// The sample in force at t (the first before it starts); samples_ must not be empty.
  const OdometrySample& sampleAt(double t) const;
  std::vector<OdometrySample> samples_;
};

/// Gyro bias from standstill (a zero-velocity update, as inertial navigation does at stops):
/// while the wheels report a speed below `standstill_mps` for `margin_s` before and after, the
/// car does not turn, so the mean gyro reading there is its bias (the margin keeps out the
/// moments a car starts or stops, when it may already turn). Each sample's yaw rate has the
/// estimate from the standstill confirmed before it subtracted (causal, as on the vehicle), once
/// at least `min_standstill_s` of it was seen; before that the readings are kept.
struct GyroBiasResult {
  WheelOdometry odometry;         ///< corrected
  double standstill_s = 0.0;      ///< standstill time seen over the whole drive [s]
  double final_bias_rad_s = 0.0;  ///< the estimate at the end [rad/s]
};
GyroBiasResult removeStandstillGyroBias(const WheelOdometry& odo, double standstill_mps = 0.15,
                                        double min_standstill_s = 2.0, double margin_s = 0.6);

/// CSV with header "t,speed_mps,yaw_rate_rad_s" and optionally ",roll_rad,pitch_rad" (written
/// when every sample has them). Throws naming the file and line.
WheelOdometry readOdometryCsv(const std::filesystem::path& path);
void writeOdometryCsv(const std::filesystem::path& path, const WheelOdometry& odo);

}  // namespace slamroute
