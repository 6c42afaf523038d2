// Simulated wheel odometry + yaw-rate gyro + IMU roll/pitch of the mapping vehicle (written with
// each drive).
#include <cmath>
#include <numbers>
#include <random>

#include "slamroute/core/Yaw.hpp"
#include "slamroute/simulate/Drive.hpp"

namespace slamroute::simulate {

WheelOdometry simulateOdometry(const Trajectory& gt, const DriveConfig& cfg, std::uint64_t seed) {
  std::mt19937_64 rng(seed ^ 0x6f646f6d65747279ULL);  // "odometry": its own stream
  std::normal_distribution<double> unit(0.0, 1.0);
  const double deg = std::numbers::pi / 180.0;
  const double scale = 1.0 + cfg.odometry_scale_sigma * unit(rng);
  const double bias = cfg.gyro_bias_sigma_deg_s * deg * unit(rng);
  // Drawn after the wheel and gyro errors so those stay what they were for a given seed.
  const bool tilt = cfg.tilt_bias_sigma_deg >= 0.0;
  std::mt19937_64 tilt_rng(seed ^ 0x74696c74ULL);  // "tilt": its own stream
  const double roll_bias = tilt ? cfg.tilt_bias_sigma_deg * deg * unit(tilt_rng) : 0.0;
  const double pitch_bias = tilt ? cfg.tilt_bias_sigma_deg * deg * unit(tilt_rng) : 0.0;
  std::vector<OdometrySample> out;
  out.reserve(gt.size());
  for (std::size_t k = 0; k + 1 < gt.size(); ++k) {
    const double dt = gt[k + 1].t - gt[k].t;
    if (!(dt > 0)) continue;
    const Pose3 d = gt[k].T_world_body.inverse() * gt[k + 1].T_world_body;
    const double yaw = yawOf(d);
    OdometrySample s;
    s.t = gt[k].t;
    // Forward speed: the wheels measure the distance rolled (signed along the heading).
    const double fwd = d.translation().head<2>().norm() * (d.translation().x() < 0 ? -1.0 : 1.0);
    s.speed_mps = fwd / dt * scale + cfg.odometry_speed_noise_mps * unit(rng);
    s.yaw_rate_rad_s = yaw / dt + bias + cfg.gyro_noise_deg_s * deg * unit(rng);
    if (tilt) {  // roll and pitch of the body at t
      const Attitude a = attitudeOf(gt[k].T_world_body.rotation());
      s.roll_rad = a.roll_rad + roll_bias + cfg.tilt_noise_deg * deg * unit(tilt_rng);
      s.pitch_rad = a.pitch_rad + pitch_bias + cfg.tilt_noise_deg * deg * unit(tilt_rng);
    }
    out.push_back(s);
  }
  return WheelOdometry(std::move(out));
}

}  // namespace slamroute::simulate
