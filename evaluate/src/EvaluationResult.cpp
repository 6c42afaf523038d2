#include "slamroute/evaluate/EvaluationResult.hpp"

#include <algorithm>
#include <cmath>

#include "EvaluationJson.hpp"
#include "slamroute/core/AtomicFile.hpp"

namespace slamroute::evaluate {
namespace fs = std::filesystem;

long long EvaluationResult::loopClosuresByPlace() const {
  return std::count_if(loops.begin(), loops.end(), [](const LoopRecord& l) { return l.by_place; });
}

namespace {

/// Adds `v` under `key` when it is finite (a NaN figure is absent from a table, as null is).
void put(std::map<std::string, double>& f, const std::string& key, double v) {
  if (std::isfinite(v)) f[key] = v;
}

void addTrajectoryFigures(const TrajectorySummary& t, std::map<std::string, double>& f) {
  put(f, "poses_matched", static_cast<double>(t.poses_matched));
  put(f, "ate_rmse_m", t.ate_rmse_m);
  put(f, "ate_mean_m", t.ate_mean_m);
  put(f, "ate_median_m", t.ate_median_m);
  put(f, "ate_max_m", t.ate_max_m);
  put(f, "rpe_trans_pct", t.rpe_trans_pct);
  put(f, "rpe_rot_deg_per_m", t.rpe_rot_deg_per_m);
  put(f, "rpe_segments", static_cast<double>(t.rpe_segments));
  put(f, "rpe_segment_m", t.rpe_segment_m);
  put(f, "rpe_segment_trans_pct", t.rpe_segment_trans_pct);
  put(f, "rpe_segment_rot_deg_per_m", t.rpe_segment_rot_deg_per_m);
  put(f, "rpe_segment_count", static_cast<double>(t.rpe_segment_count));
  put(f, "route_length_m", t.route_length_m);
  put(f, "evaluated_length_m", t.evaluated_length_m);
  if (t.end_drift_pct) put(f, "end_drift_pct", *t.end_drift_pct);
}

void addSlamFigures(const EvaluationResult& r, std::map<std::string, double>& f) {
  put(f, "gyro_standstill_s", r.gyro_standstill_s);
  put(f, "gyro_bias_deg_s", r.gyro_bias_deg_s);
  if (r.odometry_prior_sigma_deg) put(f, "odometry_prior_sigma_deg", *r.odometry_prior_sigma_deg);
  if (r.wheel_scale) put(f, "wheel_scale", *r.wheel_scale);
  if (r.imu_pitch_bias_deg) put(f, "imu_pitch_bias_deg", *r.imu_pitch_bias_deg);
  put(f, "scans", static_cast<double>(r.scans));
  put(f, "scan_stride", static_cast<double>(r.scan_stride));
  put(f, "keyframes", static_cast<double>(r.keyframes));
  put(f, "loop_closures", static_cast<double>(r.loops.size()));
  put(f, "loop_closures_by_place", static_cast<double>(r.loopClosuresByPlace()));
  put(f, "loop_candidates", static_cast<double>(r.loop_candidates));
  put(f, "loops_rejected_correction", static_cast<double>(r.loops_rejected_correction));
  put(f, "loops_rejected_ambiguous", static_cast<double>(r.loops_rejected_ambiguous));
}

void addMapFigures(const MapFigures& m, const std::string& prefix,
                   std::map<std::string, double>& f) {
  put(f, prefix + "mean_dist_m", m.mean_m);
  put(f, prefix + "median_dist_m", m.median_m);
  put(f, prefix + "p95_dist_m", m.p95_m);
  put(f, prefix + "far_share", m.far_share);
}

void addCoverageAndMapFigures(const EvaluationResult& r, std::map<std::string, double>& f) {
  put(f, "edges_visited", static_cast<double>(r.coverage.edges_visited));
  if (r.coverage.edges_total) put(f, "edges_total", static_cast<double>(*r.coverage.edges_total));
  if (r.coverage.coverage_edge_pct) put(f, "coverage_edge_pct", *r.coverage.coverage_edge_pct);
  put(f, "map_points", static_cast<double>(r.map_points));
  if (const auto& c = r.map_completeness) {
    put(f, "map_completeness.unknown_share", c->unknown_share);
    put(f, "map_completeness.frontier_share", c->frontier_share);
    put(f, "map_completeness.mean_frontier_probability", c->mean_frontier_probability);
  }
  if (!r.map || !r.map_aligned) return;
  addMapFigures(*r.map, "map_", f);
  addMapFigures(*r.map_aligned, "map_aligned_", f);
  put(f, "map_accuracy_max_m", r.map_accuracy_max_m);
}

void addReliabilityFigures(const Reliability& r, std::map<std::string, double>& f) {
  put(f, "reliability.unreliable_scans", static_cast<double>(r.unreliable_scans));
  put(f, "reliability.unreliable_share", r.unreliable_share);
  put(f, "reliability.reliable", r.reliable() ? 1.0 : 0.0);
  for (const auto& [reason, n] : r.by_reason)
    put(f, "reliability.by_reason." + reason, static_cast<double>(n));
}

}  // namespace

std::map<std::string, double> evaluationFigures(const EvaluationResult& r) {
  std::map<std::string, double> f;
  if (r.trajectory) addTrajectoryFigures(*r.trajectory, f);
  addSlamFigures(r, f);
  if (r.drift_by_label)
    for (const auto& [label, d] : *r.drift_by_label) {
      put(f, "drift_by_label." + label + ".driven_m", d.driven_m);
      put(f, "drift_by_label." + label + ".drift_pct", d.drift_pct);
      put(f, "drift_by_label." + label + ".window_drift_pct", d.window_drift_pct);
    }
  addCoverageAndMapFigures(r, f);
  addReliabilityFigures(r.reliability, f);
  return f;
}

void writeEvaluationJson(const fs::path& path, const EvaluationResult& r) {
  writeFileAtomic(path, toJson(r).dump(2) + "\n");
}

EvaluationResult readEvaluationJson(const fs::path& path) {
  if (!fs::exists(path)) throw std::runtime_error(path.string() + ": not found");
  try {
    return evaluationFromJson(nlohmann::json::parse(readFile(path)));
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(path.string() + ": not a metrics.json (" + e.what() + ")");
  }
}

}  // namespace slamroute::evaluate
