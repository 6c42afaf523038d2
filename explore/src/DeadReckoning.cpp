// DeadReckoning: odometry readings integrated into a planar pose, applied as a correction.
#include "DeadReckoning.hpp"

#include <cmath>

#include "slamroute/core/Yaw.hpp"

namespace slamroute::explore {

void DeadReckoning::step(double t, const Pose3& truth) {
  if (!last_truth_) {
    x_m_ = truth.translation().x();
    y_m_ = truth.translation().y();
    yaw_rad_ = yawOf(truth);
  } else if (const double dt = t - last_t_; dt > 0) {
    const OdometrySample s = noise_.measure(last_t_, *last_truth_, truth, dt);
    const double mid = yaw_rad_ + 0.5 * s.yaw_rate_rad_s * dt;
    x_m_ += s.speed_mps * dt * std::cos(mid);
    y_m_ += s.speed_mps * dt * std::sin(mid);
    yaw_rad_ += s.yaw_rate_rad_s * dt;
  }
  last_truth_ = truth;
  last_t_ = t;
}

Pose3 DeadReckoning::estimate(const Pose3& truth) const {
  const Eigen::AngleAxisd turn(yaw_rad_ - yawOf(truth), Vec3::UnitZ());
  Pose3 error = Pose3::Identity();
  error.linear() = turn.toRotationMatrix();
  const Vec3 moved = error.linear() * truth.translation();
  error.translation() = Vec3(x_m_ - moved.x(), y_m_ - moved.y(), 0.0);
  return error * truth;
}

}  // namespace slamroute::explore
