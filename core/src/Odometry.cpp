// Wheel odometry + gyro: integration and the odometry.csv format.
#include "slamroute/core/Odometry.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "slamroute/core/AtomicFile.hpp"

namespace slamroute {

WheelOdometry::WheelOdometry(std::vector<OdometrySample> samples) : samples_(std::move(samples)) {
  for (std::size_t i = 0; i < samples_.size(); ++i) {
    const auto& s = samples_[i];
    if (!std::isfinite(s.t) || !std::isfinite(s.speed_mps) || !std::isfinite(s.yaw_rate_rad_s))
      throw std::invalid_argument("odometry sample " + std::to_string(i) + " is not finite");
    if (std::isfinite(s.roll_rad) != std::isfinite(s.pitch_rad))
      throw std::invalid_argument("odometry sample " + std::to_string(i) +
                                  " has roll or pitch but not both");
    if (i > 0 && !(s.t > samples_[i - 1].t))
      throw std::invalid_argument("odometry sample " + std::to_string(i) + ": times must increase");
  }
}

Attitude attitudeOf(const Mat3& R) {
  return {std::atan2(R(2, 1), R(2, 2)), -std::asin(std::clamp(R(2, 0), -1.0, 1.0))};
}

const OdometrySample& WheelOdometry::sampleAt(double t) const {
  auto it = std::upper_bound(samples_.begin(), samples_.end(), t,
                             [](double v, const OdometrySample& s) { return v < s.t; });
  if (it != samples_.begin()) --it;
  return *it;
}

double WheelOdometry::yawRate(double t) const {
  return samples_.empty() ? 0.0 : sampleAt(t).yaw_rate_rad_s;
}

std::optional<Attitude> WheelOdometry::attitude(double t) const {
  if (samples_.empty() || !sampleAt(t).hasAttitude()) return std::nullopt;
  return Attitude{sampleAt(t).roll_rad, sampleAt(t).pitch_rad};
}

Pose3 WheelOdometry::motion(double t0, double t1) const {
  Pose3 M = Pose3::Identity();
  if (samples_.empty() || !(t1 > t0)) return M;
  double x = 0, y = 0, th = 0;
  // Index of the sample in force at t0.
  std::size_t k = static_cast<std::size_t>(
      std::upper_bound(samples_.begin(), samples_.end(), t0,
                       [](double v, const OdometrySample& s) { return v < s.t; }) -
      samples_.begin());
  k = k > 0 ? k - 1 : 0;
  double t = t0;
  while (t < t1) {
    const double next = k + 1 < samples_.size() ? std::max(t, samples_[k + 1].t) : t1;
    const double end = std::min(t1, next);
    const double dt = end - t;
    if (dt > 0) {
      const double w = samples_[k].yaw_rate_rad_s, v = samples_[k].speed_mps;
      const double mid = th + 0.5 * w * dt;
      x += v * std::cos(mid) * dt;
      y += v * std::sin(mid) * dt;
      th += w * dt;
    }
    t = end;
    if (k + 1 < samples_.size() && t >= samples_[k + 1].t) ++k;
  }
  M.linear() = Eigen::AngleAxisd(th, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  M.translation() = Eigen::Vector3d(x, y, 0.0);
  return M;
}

GyroBiasResult removeStandstillGyroBias(const WheelOdometry& odo, double standstill_mps,
                                        double min_standstill_s, double margin_s) {
  GyroBiasResult r;
  std::vector<OdometrySample> out = odo.samples();
  const std::size_t n = out.size();
  // Standstill samples: every sample within margin_s on both sides is below the speed.
  std::vector<char> still(n, 0);
  std::size_t lo = 0, hi = 0, fast = 0;  // window [lo, hi) and the fast samples in it
  auto isFast = [&](std::size_t j) { return std::abs(out[j].speed_mps) >= standstill_mps; };
  for (std::size_t k = 0; k < n; ++k) {
    while (hi < n && out[hi].t <= out[k].t + margin_s) fast += isFast(hi++);
    while (out[lo].t < out[k].t - margin_s) fast -= isFast(lo++);
    still[k] =
        fast == 0 && out[k].t - margin_s >= out.front().t && out[k].t + margin_s <= out.back().t;
  }
  // Causal: sample k uses the standstill samples already confirmed (margin_s behind it).
  // The bias is averaged over the raw readings (`out` is corrected as k advances).
  const std::vector<OdometrySample>& raw = odo.samples();
  double still_s = 0.0, still_sum = 0.0;
  std::size_t p = 0;
  for (std::size_t k = 0; k < n; ++k) {
    for (; p < n && out[p].t + margin_s <= out[k].t; ++p) {
      const double dt = p + 1 < n ? out[p + 1].t - out[p].t : 0.0;
      if (!still[p] || dt <= 0.0) continue;
      still_s += dt;
      still_sum += raw[p].yaw_rate_rad_s * dt;
    }
    if (still_s >= min_standstill_s) {
      r.final_bias_rad_s = still_sum / still_s;
      out[k].yaw_rate_rad_s -= r.final_bias_rad_s;
    }
  }
  r.standstill_s = still_s;
  r.odometry = WheelOdometry(std::move(out));
  return r;
}

WheelOdometry readOdometryCsv(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path.string() + ": cannot open odometry file");
  std::string line;
  std::vector<OdometrySample> out;
  int n = 0;
  while (std::getline(in, line)) {
    ++n;
    if (line.empty() || line[0] == '#' || line[0] == 't') continue;  // comment or header
    OdometrySample s;
    char c1 = 0, c2 = 0;
    std::istringstream ls(line);
    if (!(ls >> s.t >> c1 >> s.speed_mps >> c2 >> s.yaw_rate_rad_s) || c1 != ',' || c2 != ',')
      throw std::runtime_error(path.string() + ":" + std::to_string(n) +
                               ": expected t,speed_mps,yaw_rate_rad_s[,roll_rad,pitch_rad]");
    char c3 = 0, c4 = 0;
    if (ls >> c3) {  // optional IMU roll and pitch
      if (!(c3 == ',' && ls >> s.roll_rad >> c4 >> s.pitch_rad && c4 == ','))
        throw std::runtime_error(path.string() + ":" + std::to_string(n) +
                                 ": expected t,speed_mps,yaw_rate_rad_s[,roll_rad,pitch_rad]");
    }
    out.push_back(s);
  }
  try {
    return WheelOdometry(std::move(out));
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(path.string() + ": " + e.what());
  }
}

void writeOdometryCsv(const std::filesystem::path& path, const WheelOdometry& odo) {
  std::ostringstream os;
  const bool tilt =
      !odo.empty() && std::all_of(odo.samples().begin(), odo.samples().end(),
                                  [](const OdometrySample& s) { return s.hasAttitude(); });
  os << (tilt ? "t,speed_mps,yaw_rate_rad_s,roll_rad,pitch_rad\n" : "t,speed_mps,yaw_rate_rad_s\n");
  char buf[128];
  for (const auto& s : odo.samples()) {
    if (tilt)
      std::snprintf(buf, sizeof buf, "%.4f,%.5f,%.7f,%.7f,%.7f\n", s.t, s.speed_mps,
                    s.yaw_rate_rad_s, s.roll_rad, s.pitch_rad);
    else
      std::snprintf(buf, sizeof buf, "%.4f,%.5f,%.7f\n", s.t, s.speed_mps, s.yaw_rate_rad_s);
    os << buf;
  }
  writeFileAtomic(path, os.str());
}

}  // namespace slamroute
