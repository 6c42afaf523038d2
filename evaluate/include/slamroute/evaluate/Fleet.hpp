#pragma once
// Evaluation of a fleet's drive (core FleetDrive.hpp): each vehicle's SLAM runs as for a single
// drive; then keyframes of different vehicles that show the same place are matched (place
// descriptor, then ICP with the loop closure's geometric checks), and one Ceres pose graph over
// all vehicles' keyframes puts every trajectory, and so the merged map, in one frame.
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "slamroute/core/Scan.hpp"
#include "slamroute/core/Trajectory.hpp"
#include "slamroute/evaluate/Config.hpp"
#include "slamroute/evaluate/Features.hpp"
#include "slamroute/evaluate/MapAccuracy.hpp"

namespace slamroute::evaluate {

/// How the fleet's maps are joined and measured.
struct FleetMergeOptions {
  double keyframe_spacing_m = 10.0;    ///< a merge keyframe after this much driving [m]
  int target_keyframes_each_side = 2;  ///< an ICP target: the keyframe and this many each side
  double gate_m = 30.0;                ///< candidates within this of the query's estimate [m]
  /// Two closures of a pair of vehicles agree when one's correction of the other vehicle puts
  /// the other closure's keyframe within consistency_m + consistency_per_m x the path between
  /// the two closures (both vehicles; drift grows with it) of where that closure puts it. A
  /// closure is judged by its neighbours, the pair's closures within consistency_window_m of
  /// path: kept when it agrees with more than half of them and with at least
  /// min_pair_closures (itself included); one look-alike facade must not pull the graph [m].
  double consistency_m = 1.0;
  double consistency_per_m = 0.005;     ///< [m/m]
  double consistency_window_m = 200.0;  ///< [m]
  int min_pair_closures = 2;
  /// A closure needs FleetClosure::horizontal_conditioning at least this: ICP in a corridor
  /// ends where it started along the street, metres off when the two keyframes are apart
  double min_horizontal_conditioning = 0.1;
  /// Cauchy scale of the closures in the pose graph, in loop sigmas (0: least squares): a
  /// closure that many sigmas off the rest pulls little [sigmas]
  double closure_cauchy_sigmas = 3.0;
  /// A gauge, not a measurement: each vehicle's first pose as estimated, so a vehicle without
  /// closures stays where it was; far weaker than any closure, so a vehicle whose start was known
  /// only roughly follows its closures instead of being bent towards that start [m]
  double start_sigma_m = 1000.0;
  double start_sigma_rad = 10.0;  ///< ... and heading [rad]
  int map_scan_stride = 10;       ///< merged map: every n-th scan of each vehicle
  double facade_street_m = 30.0;  ///< completeness: facades within this of a driven street [m]
  double facade_sample_m = 1.0;   ///< ... sampled one point per this spacing [m]
  double covered_m = 0.5;         ///< ... covered by a map point within this [m]
  void validate() const;
};

/// One vehicle's part: what its SLAM gave and what the merge made of it.
struct FleetVehicleInput {
  std::string id;
  std::filesystem::path drive_dir;  ///< its drive folder
  Trajectory estimate;              ///< the vehicle's own SLAM estimate (world frame at start)
  Trajectory ground_truth;
  const ScanSource* scans = nullptr;
};

/// A match between keyframes of two vehicles.
struct FleetClosure {
  int vehicle_a = 0, vehicle_b = 0;    ///< a < b
  int keyframe_a = 0, keyframe_b = 0;  ///< index into each vehicle's merge keyframes
  double t_a = 0, t_b = 0;             ///< their times
  Pose3 T_a_b = Pose3::Identity();     ///< the measured pose of b's keyframe in a's
  double fitness_m2 = 0.0;
  /// The matched planes' information on the horizontal position, weakest direction over
  /// strongest (IcpTarget::translationInformation): near 0 in a street whose facades all run
  /// one way, where ICP cannot tell how far along the street b is.
  double horizontal_conditioning = 0.0;
};

struct FleetVehicleResult {
  std::string id;
  Trajectory merged;  ///< the estimate after the fleet pose graph
  int keyframes = 0;
  double own_ate_rmse_m = 0.0;       ///< own SLAM, aligned alone
  double common_ate_before_m = 0.0;  ///< own SLAM, under the fleet's one alignment
  double common_ate_after_m = 0.0;   ///< after the merge, under the fleet's one alignment
  double completeness_pct = 0.0;     ///< facades its own map covers [%]
};

struct FleetResult {
  std::vector<FleetVehicleResult> vehicles;
  std::vector<FleetClosure> closures;
  int candidates = 0;                  ///< ICP verifications tried
  int inconsistent = 0;                ///< verified, then dropped as inconsistent
  double common_ate_before_m = 0.0;    ///< all vehicles, one alignment, before the merge
  double common_ate_after_m = 0.0;     ///< ... after it
  Pose3 T_gt_est = Pose3::Identity();  ///< the one alignment (after the merge)
  double completeness_pct = 0.0;       ///< facades the merged map covers [%]
  int facade_samples = 0;
  /// Merged map points to the world mesh, clamped at map_accuracy_max_m: the single drive's
  /// map-accuracy figures (MapAccuracy.hpp), so the two read alike; as built (the frame of
  /// vehicle 0's start) and under the fleet's one alignment T_gt_est.
  MapAccuracy map_accuracy, map_aligned_accuracy;
  double map_accuracy_max_m = 0.0;
  std::vector<float> map_aligned_dist_m;  ///< per point of `map`, aligned (its top view)
  std::size_t map_points = 0;
  Cloud map;  ///< the merged map (world frame, voxel cfg.output.map_voxel_m)
};

/// Keyframes of one vehicle for the merge: estimate poses every spacing, each with its scan.
struct FleetKeyframe {
  double t = 0.0;
  std::size_t scan = 0;            ///< index in the vehicle's scan source
  Pose3 pose = Pose3::Identity();  ///< the vehicle's estimate
  double distance_m = 0.0;         ///< path driven up to it (estimate) [m]
};
std::vector<FleetKeyframe> fleetKeyframes(const Trajectory& estimate, const ScanSource& scans,
                                          double spacing_m);

/// Inter-vehicle closures between the keyframes of every pair of vehicles.
std::vector<FleetClosure> findFleetClosures(const std::vector<FleetVehicleInput>& vehicles,
                                            const std::vector<std::vector<FleetKeyframe>>& kfs,
                                            const Config& cfg, const FleetMergeOptions& opt,
                                            int* candidates);

/// The closures that agree with their pair's majority (FleetMergeOptions::consistency_m).
std::vector<FleetClosure> consistentClosures(const std::vector<FleetClosure>& closures,
                                             const std::vector<std::vector<FleetKeyframe>>& kfs,
                                             const FleetMergeOptions& opt);

/// One pose graph over all keyframes (each vehicle's chain, the closures, a weak prior on each
/// vehicle's first keyframe); returns each vehicle's estimate moved with its keyframes.
std::vector<Trajectory> mergeFleetTrajectories(const std::vector<FleetVehicleInput>& vehicles,
                                               const std::vector<std::vector<FleetKeyframe>>& kfs,
                                               const std::vector<FleetClosure>& closures,
                                               const Config& cfg, const FleetMergeOptions& opt);

/// The merge and its metrics (map from the world.ply of vehicle 0's drive folder).
FleetResult mergeFleet(const std::vector<FleetVehicleInput>& vehicles, const Config& cfg,
                       const FleetMergeOptions& opt);

}  // namespace slamroute::evaluate

namespace slamroute::evaluate {

/// Writes OUT/fleet_metrics.json (per vehicle and merged), OUT/merged_<folder>.tum (each
/// vehicle's estimate after the merge), OUT/fleet_closures.csv, OUT/merged_map.pcd and
/// OUT/merged_map_error_top.png (the aligned merged map from above, by distance to the world).
/// `folders`: each vehicle's folder name (vehicle_K).
void writeFleetOutputs(const std::filesystem::path& out, const FleetResult& r,
                       const std::vector<std::string>& folders);

}  // namespace slamroute::evaluate
