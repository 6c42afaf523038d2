// The typed summaries of a SLAM run and of its trajectory metrics that EvaluationResult holds.
#include "EvaluationSummary.hpp"

#include <cmath>
#include <numbers>

#include "EvaluationJson.hpp"
#include "slamroute/core/Yaw.hpp"
#include "slamroute/evaluate/Evaluate.hpp"

namespace slamroute::evaluate {

TrajectorySummary trajectorySummary(const TrajectoryMetrics& m) {
  TrajectorySummary t;
  t.poses_matched = static_cast<long long>(m.pairs.size());
  t.ate_rmse_m = m.ate.rmse_m;
  t.ate_mean_m = m.ate.mean_m;
  t.ate_median_m = m.ate.median_m;
  t.ate_max_m = m.ate.max_m;
  t.rpe_trans_pct = m.rpe_kitti.trans_pct;
  t.rpe_rot_deg_per_m = m.rpe_kitti.rot_deg_per_m;
  t.rpe_segments = m.rpe_kitti.segments;
  t.rpe_segment_m = m.segment_m;
  t.rpe_segment_trans_pct = m.rpe_segment.trans_pct;
  t.rpe_segment_rot_deg_per_m = m.rpe_segment.rot_deg_per_m;
  t.rpe_segment_count = m.rpe_segment.segments;
  t.route_length_m = m.route_length_m;
  t.evaluated_length_m = m.distance_m.empty() ? 0.0 : m.distance_m.back();
  t.end_drift_pct = m.end_drift_pct;
  const Eigen::Quaterniond q(m.T_gt_est.rotation());
  t.alignment_t = m.T_gt_est.translation();
  t.alignment_q_xyzw = {q.x(), q.y(), q.z(), q.w()};
  return t;
}

nlohmann::json trajectoryJson(const TrajectoryMetrics& m) { return toJson(trajectorySummary(m)); }

Reliability reliabilityOf(const SlamResult& r) {
  Reliability out;
  for (std::size_t i = 0; i < r.status.size();) {
    if (r.status[i] == FrameStatus::Ok) {
      ++i;
      continue;
    }
    std::size_t k = i;
    UnreliableStretch s;
    while (k < r.status.size() && r.status[k] != FrameStatus::Ok)
      ++s.reasons[toString(r.status[k++])];
    s.first_scan = static_cast<long long>(i);
    s.last_scan = static_cast<long long>(k - 1);
    s.t_start = r.trajectory[i].t;
    s.t_end = r.trajectory[k - 1].t;
    out.unreliable_scans += static_cast<long long>(k - i);
    for (const auto& [name, c] : s.reasons) out.by_reason[name] += c;
    out.stretches.push_back(std::move(s));
    i = k;
  }
  out.unreliable_share = r.status.empty() ? 0.0
                                          : static_cast<double>(out.unreliable_scans) /
                                                static_cast<double>(r.status.size());
  return out;
}

nlohmann::json reliabilityJson(const SlamResult& r) { return toJson(reliabilityOf(r)); }

std::vector<LoopRecord> loopRecords(const SlamResult& slam) {
  std::vector<LoopRecord> out;
  for (const auto& l : slam.loops)
    out.push_back({l.from_keyframe, l.to_keyframe, l.t_old, l.t_new, l.fitness_m2, l.correction_m,
                   l.correction_z_m, l.by_place, l.T_old_new.translation(),
                   yawOf(l.T_old_new) * 180.0 / std::numbers::pi});
  return out;
}

TimingMsPerScan timingMsPerScan(const StageTimes& t, double n) {
  return {1e3 * t.projection / n, 1e3 * t.ground / n,       1e3 * t.clustering / n,
          1e3 * t.features / n,   1e3 * t.odometry / n,     1e3 * t.mapping / n,
          1e3 * t.local_map / n,  1e3 * t.loop_closure / n, 1e3 * t.pose_graph / n,
          1e3 * t.total / n};
}

}  // namespace slamroute::evaluate
