#pragma once
// Trajectory metrics: timestamp association, SE(3) Umeyama alignment, ATE, KITTI-style RPE and
// per-SUMO-edge drift.
#include <filesystem>
#include <string>
#include <vector>

#include "slamroute/core/Trajectory.hpp"

namespace slamroute::evaluate {

struct PosePair {
  double t = 0;
  Pose3 est = Pose3::Identity();  ///< as estimated
  Pose3 gt = Pose3::Identity();
};

/// Pairs each estimate pose with the ground-truth pose nearest in time (within max_dt_s).
std::vector<PosePair> associate(const Trajectory& est, const Trajectory& gt, double max_dt_s);

/// Rigid (no scale) least-squares alignment T_gt_est of the estimate positions onto the ground
/// truth (Umeyama 1991). With fewer than 3 pairs only the translation is aligned.
Pose3 alignUmeyama(const std::vector<PosePair>& pairs);

struct AteStats {
  double rmse_m = 0, mean_m = 0, median_m = 0, max_m = 0;
};
struct RpeStats {
  double trans_pct = 0;      ///< mean translational error / segment length [%]
  double rot_deg_per_m = 0;  ///< mean rotational error / segment length [deg/m]
  int segments = 0;          ///< 0: trajectory shorter than every segment length (values NaN)
};

struct MetricsOptions {
  double max_dt_s = 0.02;
  std::vector<double> rpe_lengths_m = {100, 200, 300, 400, 500, 600, 700, 800};
  double segment_m = 50.0;
  int step_frames = 10;
};

struct TrajectoryMetrics {
  std::vector<PosePair> pairs;  ///< associated poses
  Pose3 T_gt_est = Pose3::Identity();
  std::vector<double> errors_m;    ///< per pair, after alignment
  std::vector<double> distance_m;  ///< per pair, along the ground truth
  AteStats ate;
  RpeStats rpe_kitti;    ///< over rpe_lengths_m
  RpeStats rpe_segment;  ///< over segment_m
  double segment_m = 0;
  double route_length_m = 0;
  /// The last pose against the first: the relative translation error over the distance driven
  /// between them [%] (a drive's end drift; NaN when nothing was driven).
  double end_drift_pct = 0;
};

/// Relative pose error over segments of the given lengths, starting every step frames (KITTI).
RpeStats computeRpe(const std::vector<PosePair>& pairs, const std::vector<double>& distance_m,
                    const std::vector<double>& lengths_m, int step_frames);

/// Throws std::invalid_argument when fewer than 2 poses can be associated.
TrajectoryMetrics compareTrajectories(const Trajectory& est, const Trajectory& gt,
                                      const MetricsOptions& opt);

/// One row of pose_edges.csv: which SUMO edge the vehicle was on at a ground-truth pose.
struct PoseEdge {
  int index = 0;
  double t = 0;
  std::string edge;
  double lane_pos_m = 0;
};
std::vector<PoseEdge> readPoseEdges(const std::filesystem::path& path);

/// Drift of the estimate on each SUMO edge.
struct EdgeError {
  std::string edge;
  int poses = 0, visits = 0;
  double length_m = 0;  ///< driven on this edge (sum over visits)
  double ate_mean_m = 0, ate_max_m = 0;
  double drift_pct = 0;  ///< relative translation error over each visit / its length [%]
  /// The relative translation error per metre over windows of half a visit, one from every pose
  /// of its first half, averaged (KITTI's averaging over start poses) [%]. drift_pct is one pair
  /// of poses, so the heading at a visit's first pose, often still in the turn onto the street,
  /// swings it by the street's length times that heading error; this figure is the drift along
  /// the street.
  double window_drift_pct = 0;
  double rot_deg_per_m = 0;
};
std::vector<EdgeError> perEdgeErrors(const TrajectoryMetrics& m, const std::vector<PoseEdge>& edges,
                                     double max_dt_s);
void writePerEdgeCsv(const std::filesystem::path& path, const std::vector<EdgeError>& rows);
/// per_edge.csv back; window_drift_pct is NaN from files written before it. Throws naming the file
/// and line on anything else.
std::vector<EdgeError> readPerEdgeCsv(const std::filesystem::path& path);

}  // namespace slamroute::evaluate
