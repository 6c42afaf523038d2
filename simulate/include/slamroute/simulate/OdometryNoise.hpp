#pragma once
// The errors of the simulated wheel odometry + yaw-rate gyro: a wheel-speed scale and a gyro
// bias drawn once per vehicle, white noise on every sample. simulateOdometry (Drive.hpp) turns a
// recorded ground truth into odometry.csv with it; online users (explore's dead reckoning)
// measure one step at a time with the same model and the same draws.
#include <cstdint>
#include <random>

#include "slamroute/core/Odometry.hpp"
#include "slamroute/core/Types.hpp"
#include "slamroute/simulate/DriveConfig.hpp"

namespace slamroute::simulate {

class OdometryNoise {
 public:
  OdometryNoise(const DriveConfig& cfg, std::uint64_t seed);
  /// The reading at t of a vehicle whose body moved from `from` to `to` in dt > 0 seconds:
  /// forward speed (distance rolled, signed along the heading) and yaw rate, with the errors.
  OdometrySample measure(double t, const Pose3& from, const Pose3& to, double dt);

 private:
  std::mt19937_64 rng_;
  std::normal_distribution<double> unit_{0.0, 1.0};
  double scale_ = 1.0;
  double bias_rad_s_ = 0.0;
  double speed_noise_mps_ = 0.0;
  double gyro_noise_rad_s_ = 0.0;
};

}  // namespace slamroute::simulate
