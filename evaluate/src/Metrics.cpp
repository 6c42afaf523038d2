// ATE (after SE(3) Umeyama alignment), KITTI-style RPE and per-edge drift.
#include "slamroute/evaluate/Metrics.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace slamroute::evaluate {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double angleDeg(const Pose3& T) {
  return Eigen::AngleAxisd(T.rotation()).angle() * 180.0 / std::numbers::pi;
}

/// Index of the time in sorted `times` nearest to t, or -1 when none is within max_dt.
int nearest(const std::vector<double>& times, double t, double max_dt) {
  if (times.empty()) return -1;
  const auto it = std::lower_bound(times.begin(), times.end(), t);
  int best = -1;
  double best_dt = max_dt;
  for (auto j : {it - times.begin() - 1, it - times.begin()}) {
    if (j < 0 || j >= static_cast<long>(times.size())) continue;
    const double dt = std::abs(times[static_cast<std::size_t>(j)] - t);
    if (dt <= best_dt) {
      best_dt = dt;
      best = static_cast<int>(j);
    }
  }
  return best;
}

/// The estimate's motion from pair a to pair b against the truth's (relative pose error).
Pose3 relativeError(const TrajectoryMetrics& m, std::size_t a, std::size_t b) {
  return (m.pairs[a].gt.inverse() * m.pairs[b].gt).inverse() *
         (m.pairs[a].est.inverse() * m.pairs[b].est);
}

/// Relative translation error between pairs a and b over the distance driven between them.
double relativeDrift(const TrajectoryMetrics& m, std::size_t a, std::size_t b) {
  return relativeError(m, a, b).translation().norm() / (m.distance_m[b] - m.distance_m[a]);
}

/// The mean of relativeDrift over the windows of half the visit [a, b] that start at each of its
/// pairs (the end: the first pair half the visit's length on).
double windowDrift(const TrajectoryMetrics& m, std::size_t a, std::size_t b) {
  const double half = 0.5 * (m.distance_m[b] - m.distance_m[a]);
  double sum = 0;
  int n = 0;
  std::size_t j = a;
  for (std::size_t i = a; i < b; ++i) {
    while (j < b && m.distance_m[j] - m.distance_m[i] < half) ++j;
    if (m.distance_m[j] - m.distance_m[i] < half) break;
    sum += relativeDrift(m, i, j);
    ++n;
  }
  return n > 0 ? sum / n : relativeDrift(m, a, b);
}

}  // namespace

std::vector<PosePair> associate(const Trajectory& est, const Trajectory& gt, double max_dt_s) {
  Trajectory g = gt;
  std::stable_sort(g.begin(), g.end(), [](const auto& a, const auto& b) { return a.t < b.t; });
  std::vector<double> times;
  for (const auto& p : g) times.push_back(p.t);
  std::vector<PosePair> out;
  for (const auto& e : est) {
    const int j = nearest(times, e.t, max_dt_s);
    if (j < 0) continue;
    out.push_back({e.t, e.T_world_body, g[static_cast<std::size_t>(j)].T_world_body});
  }
  std::stable_sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.t < b.t; });
  return out;
}

Pose3 alignUmeyama(const std::vector<PosePair>& pairs) {
  Pose3 T = Pose3::Identity();
  if (pairs.empty()) return T;
  const auto n = static_cast<Eigen::Index>(pairs.size());
  if (n < 3) {
    Vec3 d = Vec3::Zero();
    for (const auto& p : pairs) d += p.gt.translation() - p.est.translation();
    T.translation() = d / static_cast<double>(n);
    return T;
  }
  Eigen::Matrix3Xd src(3, n), dst(3, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    src.col(i) = pairs[static_cast<std::size_t>(i)].est.translation();
    dst.col(i) = pairs[static_cast<std::size_t>(i)].gt.translation();
  }
  T.matrix() = Eigen::umeyama(src, dst, /*with_scaling=*/false);
  return T;
}

RpeStats computeRpe(const std::vector<PosePair>& pairs, const std::vector<double>& dist,
                    const std::vector<double>& lengths_m, int step_frames) {
  RpeStats s;
  double sum_t = 0, sum_r = 0;
  const std::size_t n = pairs.size();
  const std::size_t step = static_cast<std::size_t>(std::max(1, step_frames));
  for (std::size_t i = 0; i < n; i += step) {
    for (double len : lengths_m) {
      if (len <= 0) continue;
      const auto it =
          std::lower_bound(dist.begin() + static_cast<long>(i), dist.end(), dist[i] + len);
      if (it == dist.end()) continue;
      const std::size_t j = static_cast<std::size_t>(it - dist.begin());
      const Pose3 d_gt = pairs[i].gt.inverse() * pairs[j].gt;
      const Pose3 d_est = pairs[i].est.inverse() * pairs[j].est;
      const Pose3 err = d_gt.inverse() * d_est;
      sum_t += err.translation().norm() / len;
      sum_r += angleDeg(err) / len;
      ++s.segments;
    }
  }
  if (s.segments == 0) {
    s.trans_pct = s.rot_deg_per_m = kNaN;
  } else {
    s.trans_pct = 100.0 * sum_t / s.segments;
    s.rot_deg_per_m = sum_r / s.segments;
  }
  return s;
}

TrajectoryMetrics compareTrajectories(const Trajectory& est, const Trajectory& gt,
                                      const MetricsOptions& opt) {
  TrajectoryMetrics m;
  m.pairs = associate(est, gt, opt.max_dt_s);
  if (m.pairs.size() < 2)
    throw std::invalid_argument("compare: only " + std::to_string(m.pairs.size()) +
                                " poses could be associated by timestamp (tolerance " +
                                std::to_string(opt.max_dt_s) + " s)");
  m.T_gt_est = alignUmeyama(m.pairs);
  double d = 0, sq = 0, sum = 0;
  for (std::size_t i = 0; i < m.pairs.size(); ++i) {
    if (i > 0) d += (m.pairs[i].gt.translation() - m.pairs[i - 1].gt.translation()).norm();
    m.distance_m.push_back(d);
    const double e =
        (m.T_gt_est * m.pairs[i].est.translation() - m.pairs[i].gt.translation()).norm();
    m.errors_m.push_back(e);
    sq += e * e;
    sum += e;
    m.ate.max_m = std::max(m.ate.max_m, e);
  }
  // route length from the whole ground truth, not only the associated part
  m.route_length_m = pathLength(gt);
  const double n = static_cast<double>(m.pairs.size());
  m.ate.rmse_m = std::sqrt(sq / n);
  m.ate.mean_m = sum / n;
  std::vector<double> sorted = m.errors_m;
  std::sort(sorted.begin(), sorted.end());
  const std::size_t k = sorted.size();
  m.ate.median_m = k % 2 ? sorted[k / 2] : 0.5 * (sorted[k / 2 - 1] + sorted[k / 2]);
  m.rpe_kitti = computeRpe(m.pairs, m.distance_m, opt.rpe_lengths_m, opt.step_frames);
  m.end_drift_pct = m.distance_m.back() > 0 ? 100.0 * relativeDrift(m, 0, m.pairs.size() - 1)
                                            : std::numeric_limits<double>::quiet_NaN();
  m.segment_m = opt.segment_m;
  m.rpe_segment = computeRpe(m.pairs, m.distance_m, {opt.segment_m}, opt.step_frames);
  return m;
}

std::vector<PoseEdge> readPoseEdges(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path.string() + ": cannot open");
  std::vector<PoseEdge> out;
  std::string line;
  int lineno = 0;
  while (std::getline(in, line)) {
    ++lineno;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == '#') continue;
    if (lineno == 1 && line.rfind("index", 0) == 0) continue;  // header
    std::stringstream ss(line);
    std::string a, b, c, d;
    if (!std::getline(ss, a, ',') || !std::getline(ss, b, ',') || !std::getline(ss, c, ','))
      throw std::runtime_error(path.string() + ":" + std::to_string(lineno) +
                               ": expected index,t,sumo_edge,lane_pos_m");
    std::getline(ss, d, ',');
    PoseEdge pe;
    try {
      pe.index = std::stoi(a);
      pe.t = std::stod(b);
      pe.lane_pos_m = d.empty() ? 0.0 : std::stod(d);
    } catch (const std::exception&) {
      throw std::runtime_error(path.string() + ":" + std::to_string(lineno) + ": bad number");
    }
    pe.edge = c;
    out.push_back(pe);
  }
  return out;
}

std::vector<EdgeError> perEdgeErrors(const TrajectoryMetrics& m, const std::vector<PoseEdge>& edges,
                                     double max_dt_s) {
  std::vector<double> times;
  for (const auto& p : m.pairs) times.push_back(p.t);
  // Edge of every associated pair (empty when the pair has no pose_edges row).
  std::vector<std::string> edge_of(m.pairs.size());
  for (const auto& pe : edges) {
    const int j = nearest(times, pe.t, max_dt_s);
    if (j >= 0) edge_of[static_cast<std::size_t>(j)] = pe.edge;
  }
  struct Acc {
    EdgeError e;
    double ate_sum = 0, err_t = 0, err_r = 0, drift_len = 0, window_t = 0;
  };
  std::map<std::string, Acc> acc;
  auto closeRun = [&](std::size_t a, std::size_t b) {  // pairs [a, b] on one edge
    Acc& x = acc[edge_of[a]];
    x.e.edge = edge_of[a];
    ++x.e.visits;
    const double len = m.distance_m[b] - m.distance_m[a];
    x.e.length_m += len;
    if (len < 1.0) return;  // too short to measure drift
    const Pose3 err = relativeError(m, a, b);
    x.err_t += err.translation().norm();
    x.err_r += angleDeg(err);
    x.window_t += windowDrift(m, a, b) * len;
    x.drift_len += len;
  };
  std::size_t run_start = 0;
  for (std::size_t i = 0; i < m.pairs.size(); ++i) {
    if (!edge_of[i].empty()) {
      Acc& x = acc[edge_of[i]];
      x.e.edge = edge_of[i];
      ++x.e.poses;
      x.ate_sum += m.errors_m[i];
      x.e.ate_max_m = std::max(x.e.ate_max_m, m.errors_m[i]);
    }
    const bool last = i + 1 == m.pairs.size();
    if (last || edge_of[i + 1] != edge_of[run_start]) {
      if (!edge_of[run_start].empty()) closeRun(run_start, i);
      run_start = i + 1;
    }
  }
  std::vector<EdgeError> out;
  for (auto& [id, x] : acc) {
    x.e.ate_mean_m = x.e.poses ? x.ate_sum / x.e.poses : kNaN;
    x.e.drift_pct = x.drift_len > 0 ? 100.0 * x.err_t / x.drift_len : kNaN;
    x.e.window_drift_pct = x.drift_len > 0 ? 100.0 * x.window_t / x.drift_len : kNaN;
    x.e.rot_deg_per_m = x.drift_len > 0 ? x.err_r / x.drift_len : kNaN;
    out.push_back(x.e);
  }
  return out;
}

}  // namespace slamroute::evaluate
