// validate() of the simulate config sections run by survey and drive: values with which SUMO or
// the sensors cannot work (a zero step never advances, 1e9 vehicles per km fill the memory).
#include "slamroute/core/ConfigCheck.hpp"
#include "slamroute/simulate/DepthCameraConfig.hpp"
#include "slamroute/simulate/DriveConfig.hpp"
#include "slamroute/simulate/SurveyConfig.hpp"

namespace slamroute::simulate {
using config::requireNonNegative;
using config::requirePositive;
using config::requireRange;

namespace {
/// A lane km holds at most ~130 standing cars (7.5 m each); two directions and a spare lane.
constexpr double kMaxTrafficPerKm = 400.0;
constexpr double kDay_s = 86400.0;
}  // namespace

void SurveyConfig::validate() const {
  requirePositive("route_length_m", route_length_m, 1e7);
  requireNonNegative("depart_interval_s", depart_interval_s, kDay_s);
  requireNonNegative("traffic_per_km", traffic_per_km, kMaxTrafficPerKm);
  requirePositive("trace_hz", trace_hz, 1000.0);
  requirePositive("step_length_s", step_length_s, 10.0);
  requireNonNegative("noise_sigma_m", noise_sigma_m, 1000.0);
  requireNonNegative("noise_tau_s", noise_tau_s, kDay_s);
  requireNonNegative("depth_spacing_m", depth_spacing_m, 1e6);
  requireRange("camera_height_m", camera_height_m, 0.1, 100.0);
  requirePositive("time_to_teleport_s", time_to_teleport_s, kDay_s);
  requirePositive("max_time_s", max_time_s, 30 * kDay_s);
}

void DriveConfig::validate() const {
  requirePositive("record_hz", record_hz, 1000.0);
  requirePositive("step_length_s", step_length_s, 10.0);
  requireNonNegative("traffic_per_km", traffic_per_km, kMaxTrafficPerKm);
  requireNonNegative("traffic_range_m", traffic_range_m, 10000.0);
  requireRange("mapper_speed_factor", mapper_speed_factor, 0.01, 10.0);
  requirePositive("time_to_teleport_s", time_to_teleport_s, kDay_s);
  requirePositive("min_avg_speed_mps", min_avg_speed_mps, 100.0);
  requirePositive("path_smoothing_m", path_smoothing_m, 100.0);
  requireNonNegative("odometry_scale_sigma", odometry_scale_sigma, 1.0);
  requireNonNegative("odometry_speed_noise_mps", odometry_speed_noise_mps, 100.0);
  requireNonNegative("gyro_bias_sigma_deg_s", gyro_bias_sigma_deg_s, 360.0);
  requireNonNegative("gyro_noise_deg_s", gyro_noise_deg_s, 360.0);
  // Negative tilt figures mean "no roll / pitch recorded"; only NaN and absurd ones are wrong.
  requireRange("tilt_bias_sigma_deg", tilt_bias_sigma_deg, -1e9, 90.0);
  requireRange("tilt_noise_deg", tilt_noise_deg, -1e9, 90.0);
}

void DepthCameraConfig::validate() const {
  requireRange("width", width, 1, 20000);
  requireRange("height", height, 1, 20000);
  if (!(hfov_deg > 0 && hfov_deg < 180)) config::rejectValue("hfov_deg", hfov_deg, "in (0, 180)");
  requirePositive("max_range_m", max_range_m, 65.535);
  requireNonNegative("range_sigma_m", range_sigma_m, 100.0);
}

}  // namespace slamroute::simulate
