#pragma once
// What an evaluation of a drive measured, as a typed result: evaluateDrive / evaluateScans return
// it and metrics.json is its file form (writeEvaluationJson / readEvaluationJson). Counts are
// integers, figures doubles (NaN: not measurable, null in the file).
#include <array>
#include <cstddef>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "slamroute/core/SumoCoverage.hpp"
#include "slamroute/core/Types.hpp"

namespace slamroute::evaluate {

/// The trajectory figures after aligning the estimate onto the ground truth (Metrics.hpp).
struct TrajectorySummary {
  long long poses_matched = 0;
  double ate_rmse_m = 0, ate_mean_m = 0, ate_median_m = 0, ate_max_m = 0;
  double rpe_trans_pct = 0, rpe_rot_deg_per_m = 0;  ///< KITTI lengths
  long long rpe_segments = 0;
  double rpe_segment_m = 0, rpe_segment_trans_pct = 0, rpe_segment_rot_deg_per_m = 0;
  long long rpe_segment_count = 0;
  double route_length_m = 0, evaluated_length_m = 0;
  /// The last pose against the first, per metre driven [%] (Metrics.hpp); absent from
  /// metrics.json files written before it.
  std::optional<double> end_drift_pct;
  Vec3 alignment_t = Vec3::Zero();                        ///< T_gt_est translation [m]
  std::array<double, 4> alignment_q_xyzw = {0, 0, 0, 1};  ///< T_gt_est rotation
};

/// One accepted loop closure (Slam.hpp LoopClosure) as measured.
struct LoopRecord {
  long long old_keyframe = 0, new_keyframe = 0;
  double t_old = 0, t_new = 0, fitness_m2 = 0, correction_m = 0;
  double correction_z_m = 0;  ///< the part of the correction upwards [m]
  bool by_place = false;
  Vec3 t_old_new = Vec3::Zero();  ///< measured relative translation [m]
  double yaw_old_new_deg = 0;
};

/// Length-weighted mean drift of the streets with one label (EdgeError's figures).
struct LabelDrift {
  double driven_m = 0, drift_pct = 0, window_drift_pct = 0;
};

/// Distances of the map's points to the world surface, clamped at the evaluation's max.
struct MapFigures {
  double mean_m = 0, median_m = 0, p95_m = 0, far_share = 0;
};

/// How much of the streets' surroundings the map has seen: the occupancy grid of the scans at
/// the estimated poses, over the cells within street_radius_m of a street (GP frontier map,
/// computed by the caller: `slamroute evaluate` through explore/MapCompleteness.hpp).
struct MapCompletenessFigures {
  double street_radius_m = 0;
  long long cells = 0;                   ///< grid cells near the streets
  double unknown_share = 0;              ///< of those, never seen
  double frontier_share = 0;             ///< of those, seen ground next to unknown
  double mean_frontier_probability = 0;  ///< GP frontier probability averaged there
};

struct EdgeCoverage {
  long long edges_visited = 0;
  std::optional<long long> edges_total;     ///< passenger edges of the net (when it is known)
  std::optional<double> coverage_edge_pct;  ///< visited / total [%]
  std::string note;                         ///< why the net is unknown (empty: known)
  std::optional<SumoCoverage> directed;     ///< directed SUMO edges driven (when the net is known)
};

/// Milliseconds per scan spent in each SLAM stage.
struct TimingMsPerScan {
  double projection = 0, ground = 0, clustering = 0, features = 0, odometry = 0, mapping = 0,
         local_map = 0, loop_closure = 0, pose_graph = 0, total = 0;
};

/// A run of consecutive scans whose pose is not trustworthy, with the reasons' counts.
struct UnreliableStretch {
  long long first_scan = 0, last_scan = 0;
  double t_start = 0, t_end = 0;
  std::map<std::string, long long> reasons;
};

struct Reliability {
  long long unreliable_scans = 0;
  double unreliable_share = 0;
  std::map<std::string, long long> by_reason;
  std::vector<UnreliableStretch> stretches;
  bool reliable() const { return unreliable_scans == 0; }
};

struct EvaluationResult {
  std::optional<TrajectorySummary> trajectory;  ///< none without ground truth
  double gyro_standstill_s = 0, gyro_bias_deg_s = 0;
  bool wheel_odometry = false;  ///< motion prior: odometry.csv, else const. velocity
  std::optional<double> odometry_prior_sigma_deg;  ///< with wheel odometry
  std::optional<double> wheel_scale;  ///< with wheel odometry: measured by the LiDAR (1: not)
  /// ... and the IMU's pitch bias measured at loop closures (0: not measured) [deg]
  std::optional<double> imu_pitch_bias_deg;
  long long scans = 0, scan_stride = 1, keyframes = 0;
  long long loop_candidates = 0, loops_rejected_correction = 0, loops_rejected_ambiguous = 0;
  std::vector<LoopRecord> loops;
  std::optional<std::map<std::string, LabelDrift>> drift_by_label;  ///< with edge labels
  EdgeCoverage coverage;
  long long map_points = 0;
  std::optional<MapFigures> map, map_aligned;  ///< with the world mesh (both or neither)
  double map_accuracy_max_m = 0;               ///< the clamp, with `map`
  std::optional<MapCompletenessFigures> map_completeness;  ///< with the net
  TimingMsPerScan timing_ms_per_scan;
  double scans_per_s = 0;
  Reliability reliability;

  long long loopClosuresByPlace() const;
};

/// The figures of `r` by their metrics.json key, nested keys joined by '.' (e.g.
/// "reliability.unreliable_share", "drift_by_label.rich.drift_pct"): every finite count and
/// figure except the timings and the alignment, for tables over many evaluations.
std::map<std::string, double> evaluationFigures(const EvaluationResult& r);

/// metrics.json: the result's JSON, keys sorted, 2-space indent.
void writeEvaluationJson(const std::filesystem::path& path, const EvaluationResult& r);
/// Reads a metrics.json written by writeEvaluationJson. Throws naming the file when it is missing
/// or not a metrics.json.
EvaluationResult readEvaluationJson(const std::filesystem::path& path);

}  // namespace slamroute::evaluate
