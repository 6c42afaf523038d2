// EIF prediction and loop-closure update (see Eif.hpp).
#include "slamroute/rl/Eif.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

namespace slamroute::rl {

EdgeMotion edgeMotion(const EifConfig& cfg, double length_m, double heading_rad, double weight) {
  EdgeMotion mo;
  const double d = std::max(length_m, 0.0);
  const double c = std::cos(heading_rad), s = std::sin(heading_rad);
  // Jacobian of (x + d cos h, y + d sin h, h) with respect to (x, y, h).
  mo.F(0, 2) = -d * s;
  mo.F(1, 2) = d * c;
  const double scale = 1.0 + cfg.poor_weight_gain * (1.0 - std::clamp(weight, 0.0, 1.0));
  Eigen::Matrix2d R;
  R << c, -s, s, c;
  const Eigen::Matrix2d D =
      Eigen::Vector2d(cfg.long_var_per_m * d, cfg.lat_var_per_m * d).asDiagonal();
  mo.Q.topLeftCorner<2, 2>() = scale * R * D * R.transpose();
  mo.Q(2, 2) = scale * cfg.heading_var_per_m * d;
  // Keep Q positive definite even for a zero-length edge.
  mo.Q += 1e-12 * Eigen::Matrix3d::Identity();
  return mo;
}

Eigen::Matrix3d closureNoise(const EifConfig& cfg) {
  const double cxy = std::max(cfg.closure_sigma_xy_m, 1e-6);
  const double ch = std::max(cfg.closure_sigma_heading_rad, 1e-9);
  return Eigen::Vector3d(cxy * cxy, cxy * cxy, ch * ch).asDiagonal();
}

PoseEif::PoseEif(const EifConfig& cfg) {
  const double sxy = std::max(cfg.init_sigma_xy_m, 1e-6);
  const double sh = std::max(cfg.init_sigma_heading_rad, 1e-9);
  L0_ = Eigen::Vector3d(1.0 / (sxy * sxy), 1.0 / (sxy * sxy), 1.0 / (sh * sh)).asDiagonal();
  R_lc_ = closureNoise(cfg);
  L_ = L0_;
}

void PoseEif::reset() { L_ = L0_; }

void PoseEif::drive(const EdgeMotion& mo) {
  const Eigen::Matrix3d S = L_.inverse();
  const Eigen::Matrix3d S2 = mo.F * S * mo.F.transpose() + mo.Q;
  L_ = S2.inverse();
  L_ = 0.5 * (L_ + L_.transpose());
}

void PoseEif::closeLoop(const Info3& node_info) {
  const Eigen::Matrix3d S_meas = node_info.inverse() + R_lc_;
  L_ += S_meas.inverse();
  L_ = 0.5 * (L_ + L_.transpose());
}

double PoseEif::logDetCov() const { return -std::log(L_.determinant()); }

}  // namespace slamroute::rl
