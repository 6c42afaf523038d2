#pragma once
// Noise figures of the wheel odometry + gyro that recorded a drive's odometry.csv (its data
// sheet): `slamroute drive` writes the simulated ones to odometry.yaml; a crew with real data can
// write their sensor's. evaluate weighs the gyro by them (Config odometry_prior_*).
#include <filesystem>
#include <optional>

namespace slamroute {

struct OdometrySpec {
  double scale_sigma = 0.0;            ///< wheel-speed scale error, 1 sigma (0.01 = 1 %)
  double speed_noise_mps = 0.0;        ///< white speed noise per sample, 1 sigma [m/s]
  double gyro_bias_sigma_deg_s = 0.0;  ///< yaw-rate bias, 1 sigma [deg/s]
  double gyro_noise_deg_s = 0.0;       ///< white yaw-rate noise per sample, 1 sigma [deg/s]
};

template <class V>
void visitFields(V& v, OdometrySpec& c) {
  v.field("scale_sigma", c.scale_sigma, "wheel-speed scale error, 1 sigma (0.01 = 1 %)");
  v.field("speed_noise_mps", c.speed_noise_mps,
          "wheel-speed white noise per sample, 1 sigma [m/s]");
  v.field("gyro_bias_sigma_deg_s", c.gyro_bias_sigma_deg_s, "gyro yaw-rate bias, 1 sigma [deg/s]");
  v.field("gyro_noise_deg_s", c.gyro_noise_deg_s,
          "gyro white yaw-rate noise per sample, 1 sigma [deg/s]");
}

/// Writes odometry.yaml (atomically).
void writeOdometrySpec(const std::filesystem::path& path, const OdometrySpec& spec);
/// The spec in `path`; nullopt when the file does not exist. Throws naming the file when it is
/// not YAML, has an unknown key, or a value is not a finite number >= 0.
std::optional<OdometrySpec> readOdometrySpec(const std::filesystem::path& path);

}  // namespace slamroute
