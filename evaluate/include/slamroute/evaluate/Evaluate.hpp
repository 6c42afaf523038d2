#pragma once
// `slamroute evaluate` and `slamroute compare` as library calls: run the SLAM pipeline on a drive
// folder, write estimate.tum / metrics.json / map.pcd / per_edge.csv / plots and return what was
// measured (EvaluationResult).
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "slamroute/core/Scan.hpp"
#include "slamroute/evaluate/Config.hpp"
#include "slamroute/evaluate/EvaluationResult.hpp"
#include "slamroute/evaluate/Metrics.hpp"
#include "slamroute/evaluate/Slam.hpp"

namespace slamroute::evaluate {

/// LidarSpec from a drive's sensor.yaml: the first mapping holding "channels" (top level or one
/// level down, e.g. "lidar:"); other keys are ignored. Missing file: throws naming it.
LidarSpec readSensorSpec(const std::filesystem::path& path);

MetricsOptions metricsOptions(const Config& cfg);

TrajectorySummary trajectorySummary(const TrajectoryMetrics& m);
/// The trajectory part of metrics.json (also what `compare --json` prints).
nlohmann::json trajectoryJson(const TrajectoryMetrics& m);

/// Reliability summary: per-reason counts and merged stretches of non-Ok frames.
Reliability reliabilityOf(const SlamResult& r);
/// reliabilityOf as it appears in metrics.json.
nlohmann::json reliabilityJson(const SlamResult& r);

/// Disk an evaluation of a drive of `route_km` needs in its output folder [GB = 10^9 bytes]:
/// map.pcd (~6.6 MB/km) and, with cfg.output.keyframe_clouds_on_disk, the keyframe clouds' file
/// while the SLAM runs (~23 MB/km; bench/RESULTS.md "SLAM memory"), or, with the clouds in memory,
/// twice map.pcd (its tiles wait in a file until it is written). evaluateDrive warns when the
/// folder has less free.
double evaluationDiskGb(double route_km, const Config& cfg);

/// Runs the whole evaluation of a drive folder and writes the outputs into `out`: evaluateScans
/// with the drive's groundtruth.tum (throws when it is missing or empty).
EvaluationResult evaluateDrive(const std::filesystem::path& drive, const ScanSource& source,
                               const std::filesystem::path& out, const Config& cfg,
                               const std::map<std::string, std::string>& edge_labels = {});

/// Runs the whole evaluation of the scans of `folder` and writes the outputs into `out`.
/// The estimate starts at the first ground-truth pose (so it is in the world frame); the ATE is
/// still computed after SE(3) alignment. Returns what metrics.json holds. An empty
/// `ground_truth` (a recording without one): the estimate starts at the identity and the result
/// has no trajectory metrics ("trajectory_metrics": "skipped: ..." in the file). The drive-folder
/// files that `folder` holds are used: odometry.csv / odometry.yaml (motion prior), world.ply
/// (map accuracy), pose_edges.csv (per-edge drift), world.yaml (coverage).
/// `edge_labels` (optional): a label per SUMO edge (e.g. the simulated world's street kind);
/// the result then has drift_by_label: the length-weighted mean drift per label.
EvaluationResult evaluateScans(const std::filesystem::path& folder, const ScanSource& source,
                               const Trajectory& ground_truth, const std::filesystem::path& out,
                               const Config& cfg,
                               const std::map<std::string, std::string>& edge_labels = {});

}  // namespace slamroute::evaluate
