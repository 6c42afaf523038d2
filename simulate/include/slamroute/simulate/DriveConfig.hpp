#pragma once
// Parameters of a route drive in SUMO (`slamroute drive`). The sensor itself is the "lidar"
// section (LidarConfig); `--sensor paper|vlp16|hdl32` on the command line sets lidar.preset.
namespace slamroute::simulate {

/// The mapping vehicle's body on its suspension (VehicleBody.hpp): it stands on the world's road
/// surface at its four wheels and pitches, rolls and heaves on a damped spring per axis, driven by
/// the road under the wheels and by braking, accelerating and cornering.
struct VehicleBodyConfig {
  double wheelbase_m = 2.7;          ///< front to rear axle [m]
  double track_m = 1.6;              ///< left to right wheel [m]
  double front_overhang_m = 0.9;     ///< front bumper (SUMO's reference point) to front axle [m]
  double pitch_hz = 1.4;             ///< natural frequency of the body's pitch [Hz]
  double roll_hz = 1.2;              ///< ... roll [Hz]
  double heave_hz = 1.3;             ///< ... heave [Hz]
  double damping_ratio = 0.4;        ///< of each axis (1 = critically damped)
  double pitch_deg_per_mps2 = 0.15;  ///< nose dive per m/s^2 of braking (squat: accelerating) [deg]
  double roll_deg_per_mps2 = 0.35;   ///< outward roll per m/s^2 of cornering [deg]
};

template <class V>
void visitFields(V& v, VehicleBodyConfig& c) {
  v.field("wheelbase_m", c.wheelbase_m, "front to rear axle [m]");
  v.field("track_m", c.track_m, "left to right wheel [m]");
  v.field("front_overhang_m", c.front_overhang_m, "front bumper to front axle [m]");
  v.field("pitch_hz", c.pitch_hz, "natural frequency of body pitch [Hz]");
  v.field("roll_hz", c.roll_hz, "natural frequency of body roll [Hz]");
  v.field("heave_hz", c.heave_hz, "natural frequency of body heave [Hz]");
  v.field("damping_ratio", c.damping_ratio, "damping ratio of each axis (1 = critical)");
  v.field("pitch_deg_per_mps2", c.pitch_deg_per_mps2, "nose dive per m/s^2 of braking [deg]");
  v.field("roll_deg_per_mps2", c.roll_deg_per_mps2, "outward roll per m/s^2 of cornering [deg]");
}

struct DriveConfig {
  void validate() const;    ///< values that cannot work: std::invalid_argument (ConfigValidate.cpp)
  double record_hz = 10.0;  ///< ground-truth pose rate [Hz] (a multiple of the 0.1 s step)
  double step_length_s = 0.1;   ///< SUMO simulation step [s]
  double traffic_per_km = 3.0;  ///< background vehicles kept per km of drivable road
  double traffic_range_m =
      0.0;  ///< record other vehicles within this of the sensor; 0 = LiDAR range [m]
  double mapper_speed_factor = 1.0;  ///< mapper's speed relative to the speed limit
  double time_to_teleport_s =
      300.0;  ///< SUMO teleports a car stuck this long; for the mapper this is an error [s]
  double min_avg_speed_mps =
      1.0;  ///< the drive fails when the route takes longer than length / this + 300 s [m/s]
  /// SUMO's path averaged over +- this along its length (a triangular kernel 4x as wide), so
  /// the sideways jumps SUMO's cars make between a junction's lanes become a path a car can drive
  double path_smoothing_m = 2.5;  ///< [m], > 0
  /// Wheel odometry + gyro recorded with the drive (odometry.csv, from the ground truth):
  double odometry_scale_sigma = 0.01;      ///< wheel-speed scale error, 1 sigma, one per drive
  double odometry_speed_noise_mps = 0.05;  ///< white speed noise per sample, 1 sigma [m/s]
  double gyro_bias_sigma_deg_s = 0.05;     ///< yaw-rate bias, 1 sigma, one per drive [deg/s]
  double gyro_noise_deg_s = 0.1;           ///< white yaw-rate noise per sample, 1 sigma [deg/s]
  /// IMU roll and pitch levelled against gravity (a MEMS IMU's accelerometers; LeGO-LOAM uses
  /// them). Negative = not recorded.
  double tilt_bias_sigma_deg = 0.05;  ///< roll / pitch bias, 1 sigma, one per drive [deg]
  double tilt_noise_deg = 0.1;        ///< white roll / pitch noise per sample, 1 sigma [deg]
  VehicleBodyConfig body;             ///< suspension: the sensor pose follows the road
};

template <class V>
void visitFields(V& v, DriveConfig& c) {
  v.field("record_hz", c.record_hz, "ground-truth pose rate [Hz]");
  v.field("step_length_s", c.step_length_s, "SUMO simulation step [s]");
  v.field("traffic_per_km", c.traffic_per_km, "background vehicles per km of drivable road");
  v.field("traffic_range_m", c.traffic_range_m,
          "record vehicles within this of the sensor; 0 = LiDAR range [m]");
  v.field("mapper_speed_factor", c.mapper_speed_factor, "mapper speed relative to the limit");
  v.field("time_to_teleport_s", c.time_to_teleport_s,
          "SUMO teleport time; a mapper teleport is an error [s]");
  v.field("min_avg_speed_mps", c.min_avg_speed_mps,
          "give up when slower than this on average (+300 s) [m/s]");
  v.field("path_smoothing_m", c.path_smoothing_m,
          "SUMO's path averaged over +- this along its length, so a car can drive it [m]");
  v.field("odometry_scale_sigma", c.odometry_scale_sigma,
          "wheel odometry speed scale error, 1 sigma, one per drive (0.01 = 1 %)");
  v.field("odometry_speed_noise_mps", c.odometry_speed_noise_mps,
          "wheel odometry white speed noise, 1 sigma [m/s]");
  v.field("tilt_bias_sigma_deg", c.tilt_bias_sigma_deg,
          "IMU roll/pitch bias, 1 sigma, one per drive; negative = no roll/pitch in odometry.csv "
          "[deg]");
  v.field("tilt_noise_deg", c.tilt_noise_deg, "IMU roll/pitch white noise, 1 sigma [deg]");
  v.field("gyro_bias_sigma_deg_s", c.gyro_bias_sigma_deg_s,
          "gyro yaw-rate bias, 1 sigma, one per drive [deg/s]");
  v.field("gyro_noise_deg_s", c.gyro_noise_deg_s, "gyro white yaw-rate noise, 1 sigma [deg/s]");
  v.section("body", c.body);
}

}  // namespace slamroute::simulate
