#include "TiltBias.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "RecentMedian.hpp"

namespace slamroute::evaluate::slam {

void TiltBias::addKeyframe(const Vec3& position) {
  const double step = path_m_.empty() ? 0.0 : (position - last_).norm();
  path_m_.push_back(path_m_.empty() ? 0.0 : path_m_.back() + step);
  bias_path_.push_back(bias_path_.empty() ? 0.0 : bias_path_.back() + bias_rad_ * step);
  last_ = position;
}

void TiltBias::addClosure(int old_kf, double correction_z_m) {
  const OdometryConfig& c = cfg_;
  const int newest = static_cast<int>(path_m_.size()) - 1;
  if (!(c.tilt_bias_min_path_m > 0) || old_kf < 0 || old_kf >= newest) return;
  // Before the last closure the pose graph already tied the path to the old map.
  const int from = std::max(old_kf, anchor_);
  anchor_ = newest;
  const auto f = static_cast<std::size_t>(from), n = static_cast<std::size_t>(newest);
  const double path = path_m_[n] - path_m_[f];
  if (path < c.tilt_bias_min_path_m || !std::isfinite(correction_z_m)) return;
  // correction = (b - b_in_effect) x path, so b = mean b_in_effect + correction / path.
  const std::optional<double> b =
      pushRecentMedian(implied_rad_, (bias_path_[n] - bias_path_[f] + correction_z_m) / path,
                       c.tilt_bias_closures, c.tilt_bias_min_closures);
  if (!b) return;
  const double max_rad = c.tilt_bias_max_deg * std::numbers::pi / 180.0;
  bias_rad_ = std::clamp(*b, -max_rad, max_rad);
}

}  // namespace slamroute::evaluate::slam
