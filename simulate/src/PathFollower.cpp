#include "PathFollower.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace slamroute::simulate {
namespace {

using Vec2 = Eigen::Vector2d;

constexpr double kChordHalf_m = 0.5;      // +- span of the chord that gives the path's direction
constexpr double kProjectWindow_m = 3.0;  // how far ahead along the path the nearest point may be

double wrap(double a) { return std::remainder(a, 2.0 * std::numbers::pi); }

}  // namespace

PathFollower::PathFollower(std::vector<Vec2> path, double step_m)
    : path_(std::move(path)),
      step_m_(step_m),
      angle_(path_.size(), 0.0),
      length_(path_.size(), 0.0) {
  for (std::size_t j = 1; j < path_.size(); ++j)
    length_[j] = length_[j - 1] + (path_[j] - path_[j - 1]).norm();
  // Directions from chords of +-kChordHalf_m, unwrapped; where a chord is too short to point
  // anywhere (the apex of a hairpin the smoothing folded), the previous direction holds.
  const auto n = static_cast<long>(path_.size());
  const long half = std::max(1L, std::lround(kChordHalf_m / step_m_));
  for (long j = 0; j < n; ++j) {
    const Vec2 d = path_[static_cast<std::size_t>(std::min(n - 1, j + half))] -
                   path_[static_cast<std::size_t>(std::max(0L, j - half))];
    const double prev = j > 0 ? angle_[static_cast<std::size_t>(j - 1)] : 0.0;
    const double a = d.norm() > 0.2 * kChordHalf_m ? std::atan2(d.y(), d.x()) : prev;
    angle_[static_cast<std::size_t>(j)] = j > 0 ? prev + wrap(a - prev) : a;
  }
  p_ = path_.front();
  heading_ = angle_.front();
}

template <class T>
T PathFollower::sampleAt(const std::vector<T>& v, double u) const {
  const double x = std::clamp(u / step_m_, 0.0, static_cast<double>(v.size() - 1));
  const auto j = std::min(static_cast<std::size_t>(x), v.size() - 2);
  const double f = x - static_cast<double>(j);
  return (1.0 - f) * v[j] + f * v[j + 1];
}

double PathFollower::lengthAt(double u) const { return sampleAt(length_, u); }

double PathFollower::pathCurvature(double u) const {
  const double lo = std::max(0.0, u - kChordHalf_m);
  const double hi = std::min(step_m_ * static_cast<double>(path_.size() - 1), u + kChordHalf_m);
  return hi > lo ? (sampleAt(angle_, hi) - sampleAt(angle_, lo)) / (hi - lo) : 0.0;
}

void PathFollower::drive(double distance_m) {
  if (!(distance_m > 0.0)) return;
  const auto n = static_cast<long>(std::ceil(distance_m / step_m_));
  for (long k = 0; k < n; ++k) step(distance_m / static_cast<double>(n));
}

/// One arc of length ds at a constant curvature: the path's, less k1 x the distance beside it and
/// k2 x the heading error (e'' + k2 e' + k1 e = 0 with a double root at -1 / kSettle_m).
void PathFollower::step(double ds) {
  const Vec2 q = sampleAt(path_, u_);
  const double a = sampleAt(angle_, u_);
  const Vec2 left(-std::sin(a), std::cos(a));
  const double beside = (p_ - q).dot(left);
  const double off = wrap(heading_ - a);
  const double k1 = 1.0 / (kSettle_m * kSettle_m), k2 = 2.0 / kSettle_m;
  const double kappa =
      std::clamp(pathCurvature(u_) - k1 * beside - k2 * off, -kMaxCurvature, kMaxCurvature);
  const double mid = heading_ + 0.5 * kappa * ds;
  p_ += ds * Vec2(std::cos(mid), std::sin(mid));
  heading_ = wrap(heading_ + kappa * ds);
  project();
}

/// The nearest point of the path a little ahead of the last one (never behind it, so a hairpin's
/// other leg a few metres across is not taken for where the car is).
void PathFollower::project() {
  const std::size_t first = std::min(static_cast<std::size_t>(u_ / step_m_), path_.size() - 2);
  const std::size_t last = std::min(
      path_.size() - 2, first + static_cast<std::size_t>(std::ceil(kProjectWindow_m / step_m_)));
  double best_d = INFINITY, best_u = u_;
  for (std::size_t j = first; j <= last; ++j) {
    const Vec2 seg = path_[j + 1] - path_[j];
    const double len2 = seg.squaredNorm();
    const double f = len2 > 0.0 ? std::clamp((p_ - path_[j]).dot(seg) / len2, 0.0, 1.0) : 0.0;
    const double d = (path_[j] + f * seg - p_).squaredNorm();
    if (d < best_d) {
      best_d = d;
      best_u = step_m_ * (static_cast<double>(j) + f);
    }
  }
  u_ = std::max(u_, best_u);
}

}  // namespace slamroute::simulate
