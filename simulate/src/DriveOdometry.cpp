// Simulated wheel odometry + yaw-rate gyro + IMU roll/pitch of the mapping vehicle (written with
// each drive).
#include <cmath>
#include <numbers>
#include <random>

#include "slamroute/simulate/Drive.hpp"
#include "slamroute/simulate/OdometryNoise.hpp"

namespace slamroute::simulate {

WheelOdometry simulateOdometry(const Trajectory& gt, const DriveConfig& cfg, std::uint64_t seed) {
  OdometryNoise noise(cfg, seed);
  std::normal_distribution<double> unit(0.0, 1.0);
  const double deg = std::numbers::pi / 180.0;
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
    OdometrySample s = noise.measure(gt[k].t, gt[k].T_world_body, gt[k + 1].T_world_body, dt);
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
