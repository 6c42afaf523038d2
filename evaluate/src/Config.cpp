// Validation of the evaluate config and the map of keys that moved into its sections.
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "slamroute/evaluate/Config.hpp"

namespace slamroute::evaluate {
namespace {

/// Throws "SECTION.KEY: VALUE must be ..." (the config loader puts "FILE: evaluate." before it) when `ok` is false.
struct Check {
  std::string section;
  template <class T>
  void operator()(bool ok, const char* key, T value, const char* what) const {
    if (ok) return;
    std::ostringstream os;
    os << section << "." << key << ": " << value << " " << what;
    throw std::invalid_argument(os.str());
  }
};

bool finitePositive(double x) { return std::isfinite(x) && x > 0; }
bool finiteNonNegative(double x) { return std::isfinite(x) && x >= 0; }

void validateInput(const InputConfig& c) {
  const Check check{"input"};
  check(c.scan_stride >= 1 && c.scan_stride <= 100, "scan_stride", c.scan_stride, "must be in 1..100");
  check(finiteNonNegative(c.dense_turn_rate_deg_s), "dense_turn_rate_deg_s", c.dense_turn_rate_deg_s, "must be >= 0");
  check(finiteNonNegative(c.dense_after_failure_s), "dense_after_failure_s", c.dense_after_failure_s, "must be >= 0");
  check(finiteNonNegative(c.start_s), "start_s", c.start_s, "must be >= 0");
  check(finiteNonNegative(c.end_s) && (c.end_s == 0 || c.end_s > c.start_s), "end_s", c.end_s,
        "must be 0 (to the end) or after start_s");
}

void validateFeatures(const FeaturesConfig& c) {
  const Check check{"features"};
  check(finiteNonNegative(c.min_range_m), "min_range_m", c.min_range_m, "must be >= 0");
  check(c.min_valid_points >= 1, "min_valid_points", c.min_valid_points, "must be >= 1");
  check(c.ground_angle_deg > 0 && c.ground_angle_deg < 90, "ground_angle_deg", c.ground_angle_deg, "must be in (0, 90)");
  check(c.segment_theta_deg > 0 && c.segment_theta_deg < 90, "segment_theta_deg", c.segment_theta_deg,
        "must be in (0, 90)");
  check(c.min_cluster_points >= 1, "min_cluster_points", c.min_cluster_points, "must be >= 1");
  check(c.min_line_cluster_points >= 1, "min_line_cluster_points", c.min_line_cluster_points, "must be >= 1");
  check(c.min_cluster_rings >= 1, "min_cluster_rings", c.min_cluster_rings, "must be >= 1");
  check(c.ground_column_stride >= 1, "ground_column_stride", c.ground_column_stride, "must be >= 1");
  check(c.feature_sectors >= 1 && c.feature_sectors <= 360, "feature_sectors", c.feature_sectors, "must be in 1..360");
  check(c.curvature_half_window >= 1 && c.curvature_half_window <= 50, "curvature_half_window",
        c.curvature_half_window, "must be in 1..50");
  check(c.sharp_per_sector >= 0 && c.less_sharp_per_sector >= c.sharp_per_sector, "less_sharp_per_sector",
        c.less_sharp_per_sector, "must be >= sharp_per_sector >= 0");
  check(c.flat_per_sector >= 0, "flat_per_sector", c.flat_per_sector, "must be >= 0");
  check(finitePositive(c.less_flat_voxel_m), "less_flat_voxel_m", c.less_flat_voxel_m, "must be > 0");
  check(finiteNonNegative(c.occlusion_gap_m), "occlusion_gap_m", c.occlusion_gap_m, "must be >= 0");
}

void validateOdometry(const OdometryConfig& c) {
  const Check check{"odometry"};
  check(c.iterations >= 1, "iterations", c.iterations, "must be >= 1");
  check(finitePositive(c.max_nn_m), "max_nn_m", c.max_nn_m, "must be > 0");
  check(finitePositive(c.max_step_change_m), "max_step_change_m", c.max_step_change_m, "must be > 0");
  check(finitePositive(c.max_step_change_deg), "max_step_change_deg", c.max_step_change_deg, "must be > 0");
  check(finiteNonNegative(c.max_lateral_accel_mps2), "max_lateral_accel_mps2", c.max_lateral_accel_mps2, "must be >= 0");
  check(finiteNonNegative(c.rotation_slack_deg), "rotation_slack_deg", c.rotation_slack_deg, "must be >= 0");
  check(finitePositive(c.wheel_translation_slack_m), "wheel_translation_slack_m", c.wheel_translation_slack_m, "must be > 0");
  check(finitePositive(c.wheel_rotation_slack_deg), "wheel_rotation_slack_deg", c.wheel_rotation_slack_deg, "must be > 0");
  check(finiteNonNegative(c.prior_sigma_m), "prior_sigma_m", c.prior_sigma_m, "must be >= 0");
  check(finiteNonNegative(c.prior_sigma_deg), "prior_sigma_deg", c.prior_sigma_deg, "must be >= 0");
  check(finiteNonNegative(c.prior_ref_noise_deg_s), "prior_ref_noise_deg_s", c.prior_ref_noise_deg_s, "must be >= 0");
  check(finiteNonNegative(c.prior_ref_bias_deg_s), "prior_ref_bias_deg_s", c.prior_ref_bias_deg_s, "must be >= 0");
  check(finiteNonNegative(c.prior_min_sigma_deg), "prior_min_sigma_deg", c.prior_min_sigma_deg, "must be >= 0");
  check(finitePositive(c.prior_registration_sigma_m), "prior_registration_sigma_m", c.prior_registration_sigma_m,
        "must be > 0");
  check(c.imu_tilt_weight >= 0 && c.imu_tilt_weight <= 1, "imu_tilt_weight", c.imu_tilt_weight, "must be in [0, 1]");
  check(c.failed_turn_decay >= 0 && c.failed_turn_decay <= 1, "failed_turn_decay", c.failed_turn_decay,
        "must be in [0, 1]");
  check(finiteNonNegative(c.max_yaw_accel_deg_s2), "max_yaw_accel_deg_s2", c.max_yaw_accel_deg_s2, "must be >= 0");
  check(finiteNonNegative(c.gyro_standstill_mps), "gyro_standstill_mps", c.gyro_standstill_mps, "must be >= 0");
  check(finiteNonNegative(c.gyro_min_standstill_s), "gyro_min_standstill_s", c.gyro_min_standstill_s, "must be >= 0");
  check(finiteNonNegative(c.gyro_standstill_margin_s), "gyro_standstill_margin_s", c.gyro_standstill_margin_s,
        "must be >= 0");
}

void validateMapping(const MappingConfig& c) {
  const Check check{"mapping"};
  check(c.iterations >= 1, "iterations", c.iterations, "must be >= 1");
  check(c.reassociate_every >= 1, "reassociate_every", c.reassociate_every, "must be >= 1");
  check(finitePositive(c.max_nn_m), "max_nn_m", c.max_nn_m, "must be > 0");
  check(finiteNonNegative(c.coarse_nn_m), "coarse_nn_m", c.coarse_nn_m, "must be >= 0");
  check(finitePositive(c.edge_voxel_m), "edge_voxel_m", c.edge_voxel_m, "must be > 0");
  check(finitePositive(c.surf_voxel_m), "surf_voxel_m", c.surf_voxel_m, "must be > 0");
  check(c.max_source_edges >= 1, "max_source_edges", c.max_source_edges, "must be >= 1");
  check(c.max_source_planes >= 1, "max_source_planes", c.max_source_planes, "must be >= 1");
  check(finiteNonNegative(c.local_map_update_m), "local_map_update_m", c.local_map_update_m, "must be >= 0");
  check(c.local_map_keyframes >= 1, "local_map_keyframes", c.local_map_keyframes, "must be >= 1");
  check(finitePositive(c.local_map_radius_m), "local_map_radius_m", c.local_map_radius_m, "must be > 0");
  check(finitePositive(c.keyframe_distance_m), "keyframe_distance_m", c.keyframe_distance_m, "must be > 0");
  check(finitePositive(c.keyframe_angle_deg), "keyframe_angle_deg", c.keyframe_angle_deg, "must be > 0");
  check(finitePositive(c.failed_keyframe_distance_m), "failed_keyframe_distance_m", c.failed_keyframe_distance_m,
        "must be > 0");
  check(finitePositive(c.huber_m), "huber_m", c.huber_m, "must be > 0");
  check(finitePositive(c.plane_max_dev_m), "plane_max_dev_m", c.plane_max_dev_m, "must be > 0");
  check(c.min_edge_features >= 0, "min_edge_features", c.min_edge_features, "must be >= 0");
  check(c.min_plane_features >= 0, "min_plane_features", c.min_plane_features, "must be >= 0");
  check(finiteNonNegative(c.degeneracy_min_eig), "degeneracy_min_eig", c.degeneracy_min_eig, "must be >= 0");
}

void validateRelocalise(const RelocaliseConfig& c) {
  const Check check{"relocalise"};
  check(c.inlier_drop >= 0 && c.inlier_drop <= 1, "inlier_drop", c.inlier_drop, "must be in [0, 1]");
  check(c.ref_decay >= 0 && c.ref_decay <= 1, "ref_decay", c.ref_decay, "must be in [0, 1]");
  check(c.yaw_step_deg >= 1 && c.yaw_step_deg <= 180, "yaw_step_deg", c.yaw_step_deg, "must be in [1, 180]");
  check(c.iterations >= 1, "iterations", c.iterations, "must be >= 1");
  check(c.max_points >= 1, "max_points", c.max_points, "must be >= 1");
}

void validateLoop(const LoopConfig& c) {
  const Check check{"loop"};
  check(finitePositive(c.radius_m), "radius_m", c.radius_m, "must be > 0");
  check(finiteNonNegative(c.min_time_gap_s), "min_time_gap_s", c.min_time_gap_s, "must be >= 0");
  check(c.submap_keyframes >= 0, "submap_keyframes", c.submap_keyframes, "must be >= 0");
  check(finitePositive(c.voxel_m), "voxel_m", c.voxel_m, "must be > 0");
  check(c.icp_iterations >= 1, "icp_iterations", c.icp_iterations, "must be >= 1");
  check(finitePositive(c.icp_max_corr_m), "icp_max_corr_m", c.icp_max_corr_m, "must be > 0");
  check(finitePositive(c.fitness_m2), "fitness_m2", c.fitness_m2, "must be > 0");
  check(c.min_inlier_ratio >= 0 && c.min_inlier_ratio <= 1, "min_inlier_ratio", c.min_inlier_ratio, "must be in [0, 1]");
  check(finiteNonNegative(c.cooldown_s), "cooldown_s", c.cooldown_s, "must be >= 0");
  for (double d : c.ambiguity_along_m) check(finitePositive(d), "ambiguity_along_m", d, "entries must be > 0");
  for (double d : c.ambiguity_across_m) check(finitePositive(d), "ambiguity_across_m", d, "entries must be > 0");
  check(finiteNonNegative(c.ambiguity_separation_m), "ambiguity_separation_m", c.ambiguity_separation_m, "must be >= 0");
  check(std::isfinite(c.max_correction_m), "max_correction_m", c.max_correction_m, "must be finite");
  check(finiteNonNegative(c.correction_per_m), "correction_per_m", c.correction_per_m, "must be >= 0");
  check(finiteNonNegative(c.window_per_m), "window_per_m", c.window_per_m, "must be >= 0");
  check(c.window_max_m >= c.radius_m && c.window_max_m <= 200, "window_max_m", c.window_max_m,
        "must be in [radius_m, 200]");
  check(c.correlative_yaw_deg >= 0 && c.correlative_yaw_deg <= 90, "correlative_yaw_deg", c.correlative_yaw_deg,
        "must be in [0, 90]");
  check(finiteNonNegative(c.correlative_separation_m), "correlative_separation_m", c.correlative_separation_m,
        "must be >= 0");
  check(c.correlative_max_ratio > 0 && c.correlative_max_ratio <= 1, "correlative_max_ratio",
        c.correlative_max_ratio, "must be in (0, 1]");
  check(finitePositive(c.graph_odom_sigma_m), "graph_odom_sigma_m", c.graph_odom_sigma_m, "must be > 0");
  check(finitePositive(c.graph_odom_sigma_rad), "graph_odom_sigma_rad", c.graph_odom_sigma_rad, "must be > 0");
  check(finitePositive(c.graph_loop_sigma_m), "graph_loop_sigma_m", c.graph_loop_sigma_m, "must be > 0");
  check(finitePositive(c.graph_loop_sigma_rad), "graph_loop_sigma_rad", c.graph_loop_sigma_rad, "must be > 0");
  check(finiteNonNegative(c.place_gate_per_m), "place_gate_per_m", c.place_gate_per_m, "must be >= 0");
  check(c.place_gate_max_m >= c.radius_m && std::isfinite(c.place_gate_max_m), "place_gate_max_m",
        c.place_gate_max_m, "must be >= radius_m");
  check(c.place_max_yaw_change_deg > 0 && c.place_max_yaw_change_deg <= 180, "place_max_yaw_change_deg",
        c.place_max_yaw_change_deg, "must be in (0, 180]");
  c.place.validate("loop.place");
}

void validateOutput(const OutputConfig& c, const MetricsConfig& m) {
  const Check check{"output"};
  check(c.map_voxel_m >= 0.01 && c.map_voxel_m <= 10, "map_voxel_m", c.map_voxel_m, "must be in [0.01, 10]");
  check(c.map_tile_m >= 10 && std::isfinite(c.map_tile_m), "map_tile_m", c.map_tile_m, "must be >= 10");
  const Check metrics{"metrics"};
  metrics(finitePositive(m.map_accuracy_max_m), "map_accuracy_max_m", m.map_accuracy_max_m, "must be > 0");
  metrics(finitePositive(m.assoc_max_dt_s), "assoc_max_dt_s", m.assoc_max_dt_s, "must be > 0");
  for (double l : m.rpe_lengths_m) metrics(finitePositive(l), "rpe_lengths_m", l, "entries must be > 0");
  metrics(finiteNonNegative(m.rpe_segment_m), "rpe_segment_m", m.rpe_segment_m, "must be >= 0");
  metrics(m.rpe_step_frames >= 1, "rpe_step_frames", m.rpe_step_frames, "must be >= 1");
  metrics(m.plot_size_px >= 100 && m.plot_size_px <= 8000, "plot_size_px", m.plot_size_px, "must be in 100..8000");
}

}  // namespace

void Config::validate() const {
  validateInput(input);
  validateFeatures(features);
  validateOdometry(odometry);
  validateMapping(mapping);
  validateRelocalise(relocalise);
  validateLoop(loop);
  validateOutput(output, metrics);
}

const std::vector<std::pair<const char*, const char*>>& movedConfigKeys() {
  static const std::vector<std::pair<const char*, const char*>> moved = {
      {"scan_stride", "input.scan_stride"},
      {"dense_turn_rate_deg_s", "input.dense_turn_rate_deg_s"},
      {"dense_after_failure_s", "input.dense_after_failure_s"},
      {"start_s", "input.start_s"},
      {"end_s", "input.end_s"},
      {"use_ring_field", "features.use_ring_field"},
      {"ring_zero_is_bottom", "features.ring_zero_is_bottom"},
      {"min_range_m", "features.min_range_m"},
      {"ground_max_elevation_deg", "features.ground_max_elevation_deg"},
      {"ground_angle_deg", "features.ground_angle_deg"},
      {"sensor_mount_angle_deg", "features.sensor_mount_angle_deg"},
      {"segment_theta_deg", "features.segment_theta_deg"},
      {"min_cluster_points", "features.min_cluster_points"},
      {"min_line_cluster_points", "features.min_line_cluster_points"},
      {"min_cluster_rings", "features.min_cluster_rings"},
      {"ground_column_stride", "features.ground_column_stride"},
      {"feature_sectors", "features.feature_sectors"},
      {"curvature_half_window", "features.curvature_half_window"},
      {"edge_curvature", "features.edge_curvature"},
      {"surf_curvature", "features.surf_curvature"},
      {"sharp_per_sector", "features.sharp_per_sector"},
      {"less_sharp_per_sector", "features.less_sharp_per_sector"},
      {"flat_per_sector", "features.flat_per_sector"},
      {"occlusion_gap_m", "features.occlusion_gap_m"},
      {"less_flat_voxel_m", "features.less_flat_voxel_m"},
      {"min_valid_points", "features.min_valid_points"},
      {"use_odometry", "odometry.use_wheel_odometry"},
      {"gyro_standstill_mps", "odometry.gyro_standstill_mps"},
      {"gyro_min_standstill_s", "odometry.gyro_min_standstill_s"},
      {"gyro_standstill_margin_s", "odometry.gyro_standstill_margin_s"},
      {"two_step_odometry", "odometry.two_step"},
      {"odom_iterations", "odometry.iterations"},
      {"odom_max_nn_m", "odometry.max_nn_m"},
      {"max_step_change_m", "odometry.max_step_change_m"},
      {"max_step_change_deg", "odometry.max_step_change_deg"},
      {"max_lateral_accel_mps2", "odometry.max_lateral_accel_mps2"},
      {"rotation_slack_deg", "odometry.rotation_slack_deg"},
      {"odometry_translation_slack_m", "odometry.wheel_translation_slack_m"},
      {"odometry_rotation_slack_deg", "odometry.wheel_rotation_slack_deg"},
      {"odometry_prior_sigma_m", "odometry.prior_sigma_m"},
      {"odometry_prior_sigma_deg", "odometry.prior_sigma_deg"},
      {"odometry_prior_ref_noise_deg_s", "odometry.prior_ref_noise_deg_s"},
      {"odometry_prior_ref_bias_deg_s", "odometry.prior_ref_bias_deg_s"},
      {"odometry_prior_min_sigma_deg", "odometry.prior_min_sigma_deg"},
      {"registration_sigma_m", "odometry.prior_registration_sigma_m"},
      {"imu_tilt_weight", "odometry.imu_tilt_weight"},
      {"failed_turn_decay", "odometry.failed_turn_decay"},
      {"map_iterations", "mapping.iterations"},
      {"map_reassociate_every", "mapping.reassociate_every"},
      {"map_max_nn_m", "mapping.max_nn_m"},
      {"map_edge_voxel_m", "mapping.edge_voxel_m"},
      {"map_surf_voxel_m", "mapping.surf_voxel_m"},
      {"map_max_source_edges", "mapping.max_source_edges"},
      {"map_max_source_planes", "mapping.max_source_planes"},
      {"local_map_update_m", "mapping.local_map_update_m"},
      {"local_map_keyframes", "mapping.local_map_keyframes"},
      {"local_map_radius_m", "mapping.local_map_radius_m"},
      {"keyframe_distance_m", "mapping.keyframe_distance_m"},
      {"keyframe_angle_deg", "mapping.keyframe_angle_deg"},
      {"failed_keyframe_distance_m", "mapping.failed_keyframe_distance_m"},
      {"huber_m", "mapping.huber_m"},
      {"plane_max_dev_m", "mapping.plane_max_dev_m"},
      {"min_edge_features", "mapping.min_edge_features"},
      {"min_plane_features", "mapping.min_plane_features"},
      {"degeneracy_min_eig", "mapping.degeneracy_min_eig"},
      {"degeneracy_remap", "mapping.degeneracy_remap"},
      {"map_coarse_nn_m", "mapping.coarse_nn_m"},
      {"relocalize", "relocalise.enabled"},
      {"relocalize_inlier_drop", "relocalise.inlier_drop"},
      {"relocalize_ref_decay", "relocalise.ref_decay"},
      {"relocalize_yaw_step_deg", "relocalise.yaw_step_deg"},
      {"relocalize_iterations", "relocalise.iterations"},
      {"relocalize_max_points", "relocalise.max_points"},
      {"loop_closure", "loop.enabled"},
      {"loop_radius_m", "loop.radius_m"},
      {"loop_min_time_gap_s", "loop.min_time_gap_s"},
      {"loop_submap_keyframes", "loop.submap_keyframes"},
      {"loop_voxel_m", "loop.voxel_m"},
      {"loop_icp_iterations", "loop.icp_iterations"},
      {"loop_icp_max_corr_m", "loop.icp_max_corr_m"},
      {"loop_fitness_m2", "loop.fitness_m2"},
      {"loop_min_inlier_ratio", "loop.min_inlier_ratio"},
      {"loop_cooldown_s", "loop.cooldown_s"},
      {"loop_ambiguity_along_m", "loop.ambiguity_along_m"},
      {"loop_ambiguity_across_m", "loop.ambiguity_across_m"},
      {"loop_ambiguity_separation_m", "loop.ambiguity_separation_m"},
      {"loop_ambiguity_inlier_margin", "loop.ambiguity_inlier_margin"},
      {"loop_max_correction_m", "loop.max_correction_m"},
      {"loop_correction_per_m", "loop.correction_per_m"},
      {"graph_odom_sigma_m", "loop.graph_odom_sigma_m"},
      {"graph_odom_sigma_rad", "loop.graph_odom_sigma_rad"},
      {"graph_loop_sigma_m", "loop.graph_loop_sigma_m"},
      {"graph_loop_sigma_rad", "loop.graph_loop_sigma_rad"},
      {"map_voxel_m", "output.map_voxel_m"},
      {"map_tile_m", "output.map_tile_m"},
      {"keyframe_clouds_on_disk", "output.keyframe_clouds_on_disk"},
      {"map_accuracy_max_m", "metrics.map_accuracy_max_m"},
      {"assoc_max_dt_s", "metrics.assoc_max_dt_s"},
      {"rpe_lengths_m", "metrics.rpe_lengths_m"},
      {"rpe_segment_m", "metrics.rpe_segment_m"},
      {"rpe_step_frames", "metrics.rpe_step_frames"},
      {"plot_size_px", "metrics.plot_size_px"},
  };
  return moved;
}

}  // namespace slamroute::evaluate
