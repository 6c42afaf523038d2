#include "MotionModel.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>

#include "slamroute/core/Yaw.hpp"
#include "slamroute/evaluate/MotionChecks.hpp"

namespace slamroute::evaluate::slam {

void MotionModel::setInitialMotion(const Pose3& T_first_second, double dt_s) {
  if (!(dt_s > 0)) throw std::invalid_argument("initial motion: time step must be positive");
  velocity_ = T_first_second;
  velocity_dt_ = dt_s;
  have_velocity_ = true;
}

namespace {
/// A car's part of a motion: the same yaw and travelled distance along the chord of a constant-
/// rate turn (heading yaw / 2), no sideways, vertical, roll or pitch component.
Pose3 carMotion(double yaw, double d) {
  Pose3 v = Pose3::Identity();
  v.linear() = Eigen::AngleAxisd(yaw, Vec3::UnitZ()).toRotationMatrix();
  v.translation() = Vec3(d * std::cos(yaw / 2), d * std::sin(yaw / 2), 0.0);
  return v;
}

Pose3 vehicleMotion(const Pose3& m) {
  return carMotion(yawOf(m), std::copysign(m.translation().head<2>().norm(), m.translation().x()));
}

/// `next` (a car's motion over dt) with its yaw rate moved at most max_accel * dt from the yaw
/// rate of `last` (over last_dt): a car's turn rate builds up over a second or so, so one
/// registration that turned several degrees on a feature-poor street does not set the turn of
/// the following predictions.
Pose3 boundedYawRate(const Pose3& next, double dt, const Pose3& last, double last_dt,
                     double max_accel) {
  const double rate0 = yawOf(last) / last_dt;
  const double rate = std::clamp(yawOf(next) / dt, rate0 - max_accel * dt, rate0 + max_accel * dt);
  return carMotion(rate * dt,
                   std::copysign(next.translation().head<2>().norm(), next.translation().x()));
}
}  // namespace

Pose3 MotionModel::carTurn(const Pose3& v, double dt, double max_accel) {
  const double rate = yawOf(v) / dt;
  // Two registrations in a row that agree on a turn rate beyond the bound are the car's turn:
  // SUMO turns a car by up to 90 deg/s from one scan to the next (U-turns, junctions), faster
  // than any bound, while wrong registrations on a feature-poor street scatter.
  const bool confirmed = last_rate_ && std::abs(rate - *last_rate_) <= max_accel * dt;
  last_rate_ = rate;
  return confirmed ? v : boundedYawRate(v, dt, velocity_, velocity_dt_, max_accel);
}

void MotionModel::recordFrame(double t, const Pose3& T_world) {
  if (!started_) t_fix_ = t;
  T_world_last_ = T_world;
  t_last_ = t;
  started_ = true;
}

Pose3 MotionModel::wheelMotion(double t0, double t1) const {
  Pose3 m = odometry_.motion(t0, t1);
  m.translation().head<2>() *= wheel_scale_.scale();
  return m;
}

void MotionModel::measureWheels(const Pose3& T_good, const Pose3& T_world, double dt) {
  if (odometry_.empty() || !started_) return;
  const double wheel_m = odometry_.motion(t_last_, t_last_ + dt).translation().head<2>().norm();
  wheel_scale_.observe(wheel_m, (T_good.inverse() * T_world).translation().head<2>().norm());
}

Pose3 MotionModel::predict(double t) const {
  if (!started_) return T_world_last_;
  const Pose3 v = scaledMotion(velocity_, (t - t_last_) / velocity_dt_);
  if (odometry_.empty()) return T_world_last_ * v;
  Pose3 m = wheelMotion(t_last_, t);
  if (have_velocity_) m.translation().z() = v.translation().z();
  return T_world_last_ * m;
}

Prediction MotionModel::predictStep(double t) const {
  Prediction p;
  p.t = t;
  p.T_world = predict(t);
  p.dt = t - t_last_;
  p.scale = std::max(1.0, p.dt / 0.1);
  p.speed_mps = have_velocity_ ? velocity_.translation().norm() / velocity_dt_ : 0.0;
  p.since_fix_s = std::max(p.dt, t - t_fix_);  // t_fix_ starts where t_last_ does
  return p;
}

Pose3 MotionModel::motionOver(double t, double duration) const {
  if (!odometry_.empty()) {
    Pose3 m = wheelMotion(t, t + duration);
    if (have_velocity_)
      m.translation().z() = scaledMotion(velocity_, duration / velocity_dt_).translation().z();
    return m;
  }
  if (!have_velocity_) return Pose3::Identity();
  if (recent_rates_.size() < 2) return scaledMotion(velocity_, duration / velocity_dt_);
  // The mean of the last increments: deskewing with the last one alone feeds a registration's
  // error into the next sweep's deskew with the opposite sign, a swing from scan to scan.
  Rate mean;
  for (const Rate& r : recent_rates_) {
    mean.v_mps += r.v_mps / static_cast<double>(recent_rates_.size());
    mean.w_rad_s += r.w_rad_s / static_cast<double>(recent_rates_.size());
  }
  Pose3 m = Pose3::Identity();
  const double angle = mean.w_rad_s.norm() * duration;
  if (angle > 0)
    m.linear() = Eigen::AngleAxisd(angle, mean.w_rad_s.normalized()).toRotationMatrix();
  m.translation() = mean.v_mps * duration;
  return m;
}

bool MotionModel::plausibleStep(const Pose3& pred, const Pose3& result,
                                const Prediction& step) const {
  const double slack_s = std::min(step.since_fix_s, step.dt + cfg_.odometry.slack_since_fix_max_s);
  return plausible(pred, result, cfg_, step.dt, step.speed_mps) &&
         (odometry_.empty() || plausibleWithOdometry(pred, result, cfg_, slack_s));
}

void MotionModel::addMotionPrior(AlignOptions& o, const Prediction& step) const {
  const OdometryConfig& c = cfg_.odometry;
  const bool velocity_prior =
      c.velocity_prior_along_sigma_m > 0 || c.velocity_prior_yaw_sigma_deg > 0;
  if (odometry_.empty() && !(have_velocity_ && velocity_prior)) return;
  o.prior = step.T_world;
  // Sigmas grow with the frame interval like the slack; weight = (LiDAR sigma / prior sigma)^2.
  const auto w = [&](double sigma) {
    return sigma > 0 ? std::pow(c.prior_registration_sigma_m / (sigma * step.scale), 2) : 0.0;
  };
  o.prior_weight.setZero();
  if (odometry_.empty()) {
    o.prior_weight(3) = w(c.velocity_prior_along_sigma_m);
    o.prior_fade_info(3) = c.velocity_prior_fade_info;
    o.prior_weight(2) = w(c.velocity_prior_yaw_sigma_deg * std::numbers::pi / 180.0);
    o.prior_fade_info(2) = c.velocity_prior_yaw_fade_info;
    return;
  }
  o.prior_fade_info(3) = c.prior_along_fade_info;
  o.prior_weight(2) = w(c.prior_sigma_deg * std::numbers::pi / 180.0);
  o.prior_weight(3) = o.prior_weight(4) = w(c.prior_sigma_m);
  o.prior_weight(3) += w(c.prior_along_sigma_m);  // informations of two priors add up
}

Pose3 MotionModel::levelled(const Pose3& T_world, double t) const {
  if (cfg_.odometry.imu_tilt_weight <= 0) return T_world;
  const auto a = odometry_.attitude(t);
  if (!a) return T_world;
  return evaluate::levelled(T_world, a->roll_rad, a->pitch_rad - tilt_bias_.pitchBias(),
                            cfg_.odometry.imu_tilt_weight);
}

double MotionModel::imuPitchRad(double t) const {
  const auto a = odometry_.attitude(t);
  return a ? a->pitch_rad : std::numeric_limits<double>::quiet_NaN();
}

void MotionModel::update(Outcome outcome, bool consecutive, const Pose3& T_good,
                         const Pose3& T_world, double dt) {
  if (outcome != Outcome::Failed) t_fix_ = t_last_ + dt;
  if (outcome != Outcome::Registered || !consecutive) last_rate_.reset();
  if (outcome != Outcome::Registered) recent_rates_.clear();
  if (outcome == Outcome::Failed && have_velocity_) {
    velocity_.linear() = scaledMotion(velocity_, cfg_.odometry.failed_turn_decay).linear();
  } else if (outcome == Outcome::Relocalised && have_velocity_) {
    velocity_.linear().setIdentity();
  } else if (consecutive) {
    Pose3 v = T_good.inverse() * T_world;
    if (odometry_.empty() && cfg_.odometry.vehicle_motion) {
      v = vehicleMotion(v);
      const double max_accel = cfg_.odometry.max_yaw_accel_deg_s2 * std::numbers::pi / 180.0;
      if (max_accel > 0 && have_velocity_) v = carTurn(v, std::max(1e-3, dt), max_accel);
    }
    velocity_ = v;
    velocity_dt_ = std::max(1e-3, dt);
    have_velocity_ = true;
    // A wrong pose must not make the prediction spin on: clamp to what a car can turn.
    const double angle = rotationAngle(velocity_);
    const double max_angle =
        maxTurnRate(cfg_, velocity_.translation().norm() / velocity_dt_) * velocity_dt_;
    if (angle > max_angle) velocity_.linear() = scaledMotion(velocity_, max_angle / angle).linear();
    const Eigen::AngleAxisd aa(velocity_.rotation());
    recent_rates_.push_back(
        {velocity_.translation() / velocity_dt_, aa.axis() * aa.angle() / velocity_dt_});
    while (recent_rates_.size() > static_cast<std::size_t>(cfg_.features.deskew_increments))
      recent_rates_.pop_front();
  }
}

double MotionModel::turnRateDegPerS() const {
  if (!odometry_.empty() && started_)
    return std::abs(odometry_.yawRate(t_last_)) * 180.0 / std::numbers::pi;
  if (!have_velocity_) return 0.0;
  return rotationAngle(velocity_) / velocity_dt_ * 180.0 / std::numbers::pi;
}

}  // namespace slamroute::evaluate::slam
