// OdometryNoise: per-vehicle scale and gyro bias, per-sample white noise.
#include "slamroute/simulate/OdometryNoise.hpp"

#include <numbers>

#include "slamroute/core/Yaw.hpp"

namespace slamroute::simulate {

OdometryNoise::OdometryNoise(const DriveConfig& cfg, std::uint64_t seed)
    : rng_(seed ^ 0x6f646f6d65747279ULL) {  // "odometry": its own stream
  const double deg = std::numbers::pi / 180.0;
  scale_ = 1.0 + cfg.odometry_scale_sigma * unit_(rng_);
  bias_rad_s_ = cfg.gyro_bias_sigma_deg_s * deg * unit_(rng_);
  speed_noise_mps_ = cfg.odometry_speed_noise_mps;
  gyro_noise_rad_s_ = cfg.gyro_noise_deg_s * deg;
}

OdometrySample OdometryNoise::measure(double t, const Pose3& from, const Pose3& to, double dt) {
  const Pose3 d = from.inverse() * to;
  OdometrySample s;
  s.t = t;
  const double fwd = d.translation().head<2>().norm() * (d.translation().x() < 0 ? -1.0 : 1.0);
  s.speed_mps = fwd / dt * scale_ + speed_noise_mps_ * unit_(rng_);
  s.yaw_rate_rad_s = yawOf(d) / dt + bias_rad_s_ + gyro_noise_rad_s_ * unit_(rng_);
  return s;
}

}  // namespace slamroute::simulate
