#pragma once
// The SLAM's motion model: where the vehicle is expected at the next scan (wheel odometry + gyro
// when the drive has them, else constant velocity), what motion a registration may claim, and
// the IMU's roll / pitch. It owns the last pose and the velocity estimate.
#include <deque>
#include <optional>

#include "TiltBias.hpp"
#include "WheelScale.hpp"
#include "slamroute/core/Odometry.hpp"
#include "slamroute/core/Types.hpp"
#include "slamroute/evaluate/Config.hpp"
#include "slamroute/evaluate/Registration.hpp"

namespace slamroute::evaluate::slam {

/// What the motion model expects of the next scan.
struct Prediction {
  double t = 0.0;                     ///< time of the scan [s]
  Pose3 T_world = Pose3::Identity();  ///< predicted pose
  double dt = 0.1;                    ///< time since the last frame [s]
  double scale = 1.0;                 ///< dt in units of 0.1 s, at least 1 (slacks grow with it)
  double speed_mps = 0.0;             ///< current speed estimate (0 before any motion is known)
  double since_fix_s = 0.1;           ///< time since the last registered scan, at least dt [s]
};

class MotionModel {
 public:
  /// Before the first frame the model stands at `T_world_first`.
  MotionModel(const Config& cfg, const Pose3& T_world_first)
      : cfg_(cfg),
        wheel_scale_(cfg.odometry),
        tilt_bias_(cfg.odometry),
        T_world_last_(T_world_first) {}

  void setOdometry(WheelOdometry odometry) { odometry_ = std::move(odometry); }
  void setInitialMotion(const Pose3& T_first_second, double dt_s);
  bool hasOdometry() const { return !odometry_.empty(); }
  bool hasVelocity() const { return have_velocity_; }

  /// Pose at time t: the odometry's planar motion (height from the velocity) or constant velocity.
  Pose3 predict(double t) const;
  Prediction predictStep(double t) const;
  /// Motion from t over `duration` in the body frame at t (what a sweep moves while it spins).
  Pose3 motionOver(double t, double duration) const;

  /// `result` is a motion a car can make from `pred` within the step (and, with odometry, within
  /// its slack, which counts the time since the last registered scan:
  /// OdometryConfig::slack_since_fix_max_s).
  bool plausibleStep(const Pose3& pred, const Pose3& result, const Prediction& step) const;
  /// Prior of a scan-to-map towards the prediction: the odometry's (along the heading, yaw, x / y),
  /// or without odometry the constant velocity's (along the heading, yaw); the along priors and
  /// the constant velocity's yaw fade out where the scan holds that direction itself.
  void addMotionPrior(AlignOptions& o, const Prediction& step) const;
  /// Roll and pitch moved towards the IMU's at time t (OdometryConfig::imu_tilt_weight), its
  /// pitch less the bias measured at loop closures.
  Pose3 levelled(const Pose3& T_world, double t) const;

  /// How the last scan went, for the next prediction.
  enum class Outcome { Registered, Failed, Relocalised };
  /// Updates the velocity from a registered scan that directly follows the last good one
  /// (`consecutive`): T_good -> T_world over dt; a failed scan keeps the speed and lets the turn
  /// fade; a relocalised one is a correction, not motion (straight ahead at the same speed).
  void update(Outcome outcome, bool consecutive, const Pose3& T_good, const Pose3& T_world,
              double dt);
  /// A well-conditioned registration T_good -> T_world over dt, following the last frame,
  /// measures the wheels' scale (OdometryConfig::wheel_scale_stretch_m).
  void measureWheels(const Pose3& T_good, const Pose3& T_world, double dt);
  double wheelScale() const { return wheel_scale_.scale(); }
  /// A keyframe at `position`, and a closure from keyframe `old_kf` to the newest that moved it
  /// up by `correction_z_m`: they measure the IMU's pitch bias (OdometryConfig::tilt_bias_*).
  void keyframeAt(const Vec3& position) { tilt_bias_.addKeyframe(position); }
  void measureTilt(int old_kf, double correction_z_m) {
    tilt_bias_.addClosure(old_kf, correction_z_m);
  }
  /// The pose graph's estimate (LoopConfig::graph_imu_pitch_sigma_deg) in place of measureTilt's.
  void assumePitchBias(double bias_rad) { tilt_bias_.assume(bias_rad); }
  double pitchBiasRad() const { return tilt_bias_.pitchBias(); }
  /// The IMU's pitch at t as read, bias included [rad]; NaN without an IMU.
  double imuPitchRad(double t) const;
  /// Records the pose the frame at t ended with (the next prediction starts there).
  void recordFrame(double t, const Pose3& T_world);

  Pose3 lastPose() const { return T_world_last_; }
  double lastTime() const { return t_last_; }
  bool started() const { return started_; }
  /// Turn rate [deg/s]: the gyro's at the last frame with odometry, else the velocity's.
  double turnRateDegPerS() const;

 private:
  const Config& cfg_;
  WheelOdometry odometry_;
  WheelScale wheel_scale_;
  TiltBias tilt_bias_;
  Pose3 T_world_last_;
  double t_last_ = 0.0;
  double t_fix_ = 0.0;  ///< time of the last registered (or relocalised) scan [s]
  bool started_ = false;
  Pose3 velocity_ = Pose3::Identity();  ///< motion over velocity_dt_, body frame
  double velocity_dt_ = 0.1;            ///< [s]
  bool have_velocity_ = false;          ///< measured (or given), not the initial guess
  /// The turn rate the last registration measured, when it directly followed another [rad/s].
  std::optional<double> last_rate_;
  /// The velocity after each of the last FeaturesConfig::deskew_increments registrations that
  /// followed the frame before, as rates: the sweep's motion without odometry.
  struct Rate {
    Vec3 v_mps = Vec3::Zero();
    Vec3 w_rad_s = Vec3::Zero();
  };
  std::deque<Rate> recent_rates_;

  /// A car's motion `v` over dt with its turn rate at most max_accel * dt from the velocity's,
  /// unless the registration before measured the same turn rate (within that bound).
  Pose3 carTurn(const Pose3& v, double dt, double max_accel);
  /// The wheels' planar motion t0 -> t1 at the measured scale.
  Pose3 wheelMotion(double t0, double t1) const;
};

}  // namespace slamroute::evaluate::slam
