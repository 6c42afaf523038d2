// makeDrivable: SUMO's recorded path averaged along its own length, then driven by a car.
#include "slamroute/simulate/DrivablePath.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "PathFollower.hpp"

namespace slamroute::simulate {
namespace {

using Vec2 = Eigen::Vector2d;

constexpr double kStep_m = 0.1;        // spacing of the path resampled along its length
constexpr double kTimeWindow_s = 0.5;  // +- window of the position-along-path average

Vec2 xyOf(const StampedPose& p) { return p.T_world_body.translation().head<2>(); }

/// Distance driven up to each pose, along the recorded positions.
std::vector<double> arcLengths(const Trajectory& traj) {
  std::vector<double> s(traj.size(), 0.0);
  for (std::size_t i = 1; i < traj.size(); ++i)
    s[i] = s[i - 1] + (xyOf(traj[i]) - xyOf(traj[i - 1])).norm();
  return s;
}

/// Each value the mean of those within +-k samples; beyond the ends the sequence continues as
/// its mirror image through the end value, so the ends stay and a steady rise stays steady. A
/// non-decreasing sequence stays non-decreasing.
std::vector<double> movingAverage(const std::vector<double>& v, std::size_t k) {
  const std::size_t n = v.size();
  auto value = [&](long i) {
    const long last = static_cast<long>(n) - 1;
    if (i < 0) return 2.0 * v.front() - v[static_cast<std::size_t>(std::min(-i, last))];
    if (i > last) return 2.0 * v.back() - v[static_cast<std::size_t>(std::max(2 * last - i, 0L))];
    return v[static_cast<std::size_t>(i)];
  };
  std::vector<double> out(n);
  const auto kl = static_cast<long>(k);
  double sum = 0.0;
  for (long j = -kl; j <= kl; ++j) sum += value(j);
  for (std::size_t i = 0; i < n; ++i) {
    out[i] = sum / static_cast<double>(2 * k + 1);
    const auto il = static_cast<long>(i);
    sum += value(il + kl + 1) - value(il - kl);
  }
  return out;
}

/// The polyline through the poses, sampled every kStep_m along its length.
std::vector<Vec2> resample(const Trajectory& traj, const std::vector<double>& s) {
  const auto m = static_cast<std::size_t>(std::ceil(s.back() / kStep_m));
  std::vector<Vec2> out(m + 1);
  std::size_t seg = 0;
  for (std::size_t j = 0; j <= m; ++j) {
    const double u = std::min(s.back(), static_cast<double>(j) * kStep_m);
    while (seg + 2 < traj.size() && s[seg + 1] < u) ++seg;
    const double len = s[seg + 1] - s[seg];
    const double f = len > 0.0 ? std::clamp((u - s[seg]) / len, 0.0, 1.0) : 0.0;
    out[j] = (1.0 - f) * xyOf(traj[seg]) + f * xyOf(traj[seg + 1]);
  }
  return out;
}

/// Mean over +-h samples; beyond its ends the path continues as its mirror image through the
/// end point, so the ends stay where they are and a straight end stays straight.
std::vector<Vec2> boxFilter(const std::vector<Vec2>& p, std::size_t h) {
  const std::size_t n = p.size();
  std::vector<Vec2> ext;
  ext.reserve(n + 2 * h);
  for (std::size_t k = h; k >= 1; --k) ext.push_back(2.0 * p.front() - p[std::min(k, n - 1)]);
  ext.insert(ext.end(), p.begin(), p.end());
  for (std::size_t k = 1; k <= h; ++k)
    ext.push_back(2.0 * p.back() - p[n - 1 - std::min(k, n - 1)]);
  std::vector<Vec2> prefix(ext.size() + 1, Vec2::Zero()), out(n);
  for (std::size_t i = 0; i < ext.size(); ++i) prefix[i + 1] = prefix[i] + ext[i];
  for (std::size_t i = 0; i < n; ++i)
    out[i] = (prefix[i + 2 * h + 1] - prefix[i]) / static_cast<double>(2 * h + 1);
  return out;
}

/// A car driving the smooth path, one pose after the other: each step as far as the smooth path
/// is long between the two poses' positions along it, a little further while the car is behind
/// (after a turn it took wider than the path) and a little less while ahead, so it keeps pace
/// without jumps.
void follow(const std::vector<Vec2>& path, const std::vector<double>& s, std::vector<Vec2>& xy,
            std::vector<double>& yaw) {
  constexpr double kCatchUp = 0.2;  // [1/m]: the speed's share added per metre behind
  PathFollower car(path, kStep_m);
  double last = car.lengthAt(s.front());  // the path's length to the previous pose's place on it
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (i > 0) {
      const double next = car.lengthAt(s[i]);
      const double pace = std::clamp(1.0 + kCatchUp * (last - car.lengthAt(car.along())), 0.5, 1.5);
      car.drive(std::max(0.0, next - last) * pace);
      last = next;
    }
    xy[i] = car.position();
    yaw[i] = car.heading();
  }
}

/// Poses with the new (x, y) and heading; height and pitch as recorded.
void setPoses(Trajectory& traj, const std::vector<Vec2>& xy, const std::vector<double>& yaw) {
  for (std::size_t i = 0; i < traj.size(); ++i) {
    Pose3& T = traj[i].T_world_body;
    const double pitch = std::asin(std::clamp(Vec3(T.linear().col(0)).z(), -1.0, 1.0));
    T.translation().head<2>() = xy[i];
    T.linear() =
        (Eigen::AngleAxisd(yaw[i], Vec3::UnitZ()) * Eigen::AngleAxisd(-pitch, Vec3::UnitY()))
            .toRotationMatrix();
  }
}

}  // namespace

void makeDrivable(Trajectory& traj, double smoothing_m) {
  if (!(smoothing_m > 0.0)) throw std::invalid_argument("drive path smoothing must be > 0 m");
  if (traj.size() < 2) return;
  const std::vector<double> s_raw = arcLengths(traj);
  if (s_raw.back() < 2.0 * kStep_m) return;  // standing all along: nothing to smooth
  // Position along the path averaged in time, so a sideways step's length is spread over 1 s.
  const double dt = (traj.back().t - traj.front().t) / static_cast<double>(traj.size() - 1);
  const auto k =
      dt > 0.0 ? static_cast<std::size_t>(std::max(1.0, std::round(kTimeWindow_s / dt))) : 1;
  const std::vector<double> s = movingAverage(s_raw, k);
  // The path averaged along its length twice (a triangular kernel): curvature stays bounded.
  const auto h = static_cast<std::size_t>(std::max(1.0, std::round(smoothing_m / kStep_m)));
  const std::vector<Vec2> path = boxFilter(boxFilter(resample(traj, s_raw), h), h);
  // A car drives it: no step sideways, turns no tighter than a car can.
  std::vector<Vec2> xy(traj.size());
  std::vector<double> yaw(traj.size());
  follow(path, s, xy, yaw);
  setPoses(traj, xy, yaw);
}

}  // namespace slamroute::simulate
