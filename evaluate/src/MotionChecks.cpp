// Motion plausibility checks (see MotionChecks.hpp).
#include "slamroute/evaluate/MotionChecks.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "slamroute/core/Odometry.hpp"
#include "slamroute/core/Yaw.hpp"

namespace slamroute::evaluate {

double rotationAngle(const Pose3& T) { return Eigen::AngleAxisd(T.rotation()).angle(); }

Pose3 scaledMotion(const Pose3& m, double f) {
  const Eigen::AngleAxisd aa(m.rotation());
  Pose3 out = Pose3::Identity();
  out.linear() = Eigen::AngleAxisd(aa.angle() * f, aa.axis()).toRotationMatrix();
  out.translation() = m.translation() * f;
  return out;
}

double maxTurnRate(const Config& cfg, double speed_mps) {
  const double cap = cfg.odometry.max_step_change_deg * std::numbers::pi / 180.0 / 0.1;
  if (cfg.odometry.max_lateral_accel_mps2 <= 0) return cap;
  return std::min(cap, cfg.odometry.max_lateral_accel_mps2 / std::max(speed_mps, 0.5));
}

bool plausible(const Pose3& pred, const Pose3& result, const Config& cfg, double dt,
               double speed_mps) {
  const Pose3 d = pred.inverse() * result;
  const double scale = std::max(1.0, dt / 0.1);
  const double max_rot =
      maxTurnRate(cfg, speed_mps) * dt + cfg.odometry.rotation_slack_deg * std::numbers::pi / 180.0;
  return d.translation().norm() <= scale * cfg.odometry.max_step_change_m &&
         rotationAngle(d) <= max_rot;
}

bool plausibleWithOdometry(const Pose3& pred, const Pose3& result, const Config& cfg, double dt) {
  const Pose3 d = pred.inverse() * result;
  const double scale = std::max(1.0, dt / 0.1);
  const double yaw = std::abs(yawOf(d));
  return d.translation().head<2>().norm() <= scale * cfg.odometry.wheel_translation_slack_m &&
         yaw <= scale * cfg.odometry.wheel_rotation_slack_deg * std::numbers::pi / 180.0;
}

bool plausibleLoopCorrection(double correction_m, double driven_m, const Config& cfg) {
  if (cfg.loop.max_correction_m < 0) return true;
  return correction_m <=
         cfg.loop.max_correction_m + cfg.loop.correction_per_m * std::max(0.0, driven_m);
}

Pose3 levelled(const Pose3& T, double roll_rad, double pitch_rad, double w) {
  const Mat3 R = T.rotation();
  const double yaw = yawOf(R);
  const Attitude now = attitudeOf(R);
  const auto towards = [w](double a, double b) {
    return a + w * std::remainder(b - a, 2.0 * std::numbers::pi);
  };
  Pose3 out = T;
  out.linear() = (Eigen::AngleAxisd(yaw, Vec3::UnitZ()) *
                  Eigen::AngleAxisd(towards(now.pitch_rad, pitch_rad), Vec3::UnitY()) *
                  Eigen::AngleAxisd(towards(now.roll_rad, roll_rad), Vec3::UnitX()))
                     .toRotationMatrix();
  return out;
}

double yawPriorSigmaDeg(const Config& cfg, const std::optional<OdometrySpec>& spec) {
  const double ref =
      std::hypot(cfg.odometry.prior_ref_noise_deg_s, cfg.odometry.prior_ref_bias_deg_s);
  if (cfg.odometry.prior_sigma_deg <= 0 || !spec || !(ref > 0)) return cfg.odometry.prior_sigma_deg;
  const double gyro = std::hypot(spec->gyro_noise_deg_s, spec->gyro_bias_sigma_deg_s);
  return std::max(cfg.odometry.prior_min_sigma_deg, cfg.odometry.prior_sigma_deg * gyro / ref);
}

}  // namespace slamroute::evaluate
