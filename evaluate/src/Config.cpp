// validate() of the evaluate config sections: values with which the SLAM or the metrics cannot
// work (no iterations, a zero voxel, a sigma that makes the pose graph singular).
#include "slamroute/evaluate/Config.hpp"

#include <cmath>

#include "slamroute/core/ConfigCheck.hpp"

namespace slamroute::evaluate {
using config::rejectValue;
using config::requireNonNegative;
using config::requirePositive;
using config::requireRange;

namespace {
constexpr int kMaxCount = 100000000;  ///< upper bound of counts that have no natural one
}  // namespace

void InputConfig::validate() const {
  requireRange("scan_stride", scan_stride, 1, 100);
  requireNonNegative("dense_turn_rate_deg_s", dense_turn_rate_deg_s);
  requireNonNegative("dense_after_failure_s", dense_after_failure_s);
  requireNonNegative("start_s", start_s);
  requireNonNegative("end_s", end_s);
  if (end_s != 0 && !(end_s > start_s))
    rejectValue("end_s", end_s, "0 (to the end) or after start_s");
}

void FeaturesConfig::validate() const {
  requireNonNegative("min_range_m", min_range_m);
  requireRange("deskew_increments", deskew_increments, 1, 10);
  requireRange("min_valid_points", min_valid_points, 1, kMaxCount);
  if (!(ground_angle_deg > 0 && ground_angle_deg < 90))
    rejectValue("ground_angle_deg", ground_angle_deg, "in (0, 90)");
  if (!(segment_theta_deg > 0 && segment_theta_deg < 90))
    rejectValue("segment_theta_deg", segment_theta_deg, "in (0, 90)");
  requireRange("min_cluster_points", min_cluster_points, 1, kMaxCount);
  requireRange("min_line_cluster_points", min_line_cluster_points, 1, kMaxCount);
  requireRange("min_cluster_rings", min_cluster_rings, 1, kMaxCount);
  requireRange("ground_column_stride", ground_column_stride, 1, kMaxCount);
  requireRange("feature_sectors", feature_sectors, 1, 360);
  requireRange("curvature_half_window", curvature_half_window, 1, 50);
  requireRange("sharp_per_sector", sharp_per_sector, 0, kMaxCount);
  requireRange("less_sharp_per_sector", less_sharp_per_sector, sharp_per_sector, kMaxCount);
  requireRange("flat_per_sector", flat_per_sector, 0, kMaxCount);
  requirePositive("less_flat_voxel_m", less_flat_voxel_m);
  requireNonNegative("occlusion_gap_m", occlusion_gap_m);
}

void OdometryConfig::validate() const {
  requireRange("iterations", iterations, 1, kMaxCount);
  requirePositive("max_nn_m", max_nn_m);
  requirePositive("max_step_change_m", max_step_change_m);
  requirePositive("max_step_change_deg", max_step_change_deg);
  requireNonNegative("max_lateral_accel_mps2", max_lateral_accel_mps2);
  requireNonNegative("rotation_slack_deg", rotation_slack_deg);
  requirePositive("wheel_translation_slack_m", wheel_translation_slack_m);
  requirePositive("wheel_rotation_slack_deg", wheel_rotation_slack_deg);
  requireNonNegative("slack_since_fix_max_s", slack_since_fix_max_s);
  requireNonNegative("prior_sigma_m", prior_sigma_m);
  requireNonNegative("prior_along_sigma_m", prior_along_sigma_m);
  requireNonNegative("prior_along_fade_info", prior_along_fade_info);
  requireNonNegative("velocity_prior_along_sigma_m", velocity_prior_along_sigma_m);
  requireNonNegative("velocity_prior_fade_info", velocity_prior_fade_info);
  requireNonNegative("velocity_prior_yaw_sigma_deg", velocity_prior_yaw_sigma_deg);
  requireNonNegative("velocity_prior_yaw_fade_info", velocity_prior_yaw_fade_info);
  requireNonNegative("wheel_scale_stretch_m", wheel_scale_stretch_m);
  requireRange("wheel_scale_max", wheel_scale_max, 0.0, 0.5);
  requireRange("wheel_scale_stretches", wheel_scale_stretches, 1, kMaxCount);
  requireRange("wheel_scale_min_stretches", wheel_scale_min_stretches, 1, wheel_scale_stretches);
  requireNonNegative("prior_sigma_deg", prior_sigma_deg);
  requireNonNegative("prior_ref_noise_deg_s", prior_ref_noise_deg_s);
  requireNonNegative("prior_ref_bias_deg_s", prior_ref_bias_deg_s);
  requireNonNegative("prior_min_sigma_deg", prior_min_sigma_deg);
  requirePositive("prior_registration_sigma_m", prior_registration_sigma_m);
  requireRange("imu_tilt_weight", imu_tilt_weight, 0.0, 1.0);
  requireNonNegative("tilt_bias_min_path_m", tilt_bias_min_path_m);
  requireRange("tilt_bias_closures", tilt_bias_closures, 1, kMaxCount);
  requireRange("tilt_bias_min_closures", tilt_bias_min_closures, 1, tilt_bias_closures);
  requireRange("tilt_bias_max_deg", tilt_bias_max_deg, 0.0, 5.0);
  requireRange("failed_turn_decay", failed_turn_decay, 0.0, 1.0);
  requireNonNegative("max_yaw_accel_deg_s2", max_yaw_accel_deg_s2);
  requireNonNegative("gyro_standstill_mps", gyro_standstill_mps);
  requireNonNegative("gyro_min_standstill_s", gyro_min_standstill_s);
  requireNonNegative("gyro_standstill_margin_s", gyro_standstill_margin_s);
}

void MappingConfig::validate() const {
  requireRange("iterations", iterations, 1, kMaxCount);
  requireRange("iterations_without_odometry", iterations_without_odometry, 1, kMaxCount);
  requireRange("reassociate_every", reassociate_every, 1, kMaxCount);
  requirePositive("max_nn_m", max_nn_m);
  requireNonNegative("coarse_nn_m", coarse_nn_m);
  requirePositive("edge_voxel_m", edge_voxel_m);
  requirePositive("surf_voxel_m", surf_voxel_m);
  requireRange("max_source_edges", max_source_edges, 1, kMaxCount);
  requireRange("max_source_planes", max_source_planes, 1, kMaxCount);
  requireNonNegative("local_map_update_m", local_map_update_m);
  requireRange("local_map_keyframes", local_map_keyframes, 1, kMaxCount);
  requirePositive("local_map_radius_m", local_map_radius_m);
  requirePositive("keyframe_distance_m", keyframe_distance_m);
  requirePositive("keyframe_angle_deg", keyframe_angle_deg);
  requirePositive("failed_keyframe_distance_m", failed_keyframe_distance_m);
  requirePositive("huber_m", huber_m);
  requirePositive("plane_max_dev_m", plane_max_dev_m);
  requireRange("edge_weight", edge_weight, 1e-6, 1.0);
  requireRange("edge_weight_without_odometry", edge_weight_without_odometry, 1e-6, 1.0);
  requireRange("min_edge_features", min_edge_features, 0, kMaxCount);
  requireRange("min_plane_features", min_plane_features, 0, kMaxCount);
  requireNonNegative("degeneracy_min_eig", degeneracy_min_eig);
}

void RelocaliseConfig::validate() const {
  requireRange("inlier_drop", inlier_drop, 0.0, 1.0);
  requireRange("ref_decay", ref_decay, 0.0, 1.0);
  requireRange("yaw_step_deg", yaw_step_deg, 1.0, 180.0);
  requireRange("iterations", iterations, 1, kMaxCount);
  requireRange("max_points", max_points, 1, kMaxCount);
}

void LoopConfig::validate() const {
  requirePositive("radius_m", radius_m);
  requirePositive("max_height_gap_m", max_height_gap_m);
  requireNonNegative("min_time_gap_s", min_time_gap_s);
  requireRange("submap_keyframes", submap_keyframes, 0, kMaxCount);
  requirePositive("voxel_m", voxel_m);
  requireRange("icp_iterations", icp_iterations, 1, kMaxCount);
  requirePositive("icp_max_corr_m", icp_max_corr_m);
  requirePositive("fitness_m2", fitness_m2);
  requireRange("min_inlier_ratio", min_inlier_ratio, 0.0, 1.0);
  requireNonNegative("cooldown_s", cooldown_s);
  for (double d : ambiguity_along_m) requirePositive("ambiguity_along_m entries", d);
  for (double d : ambiguity_across_m) requirePositive("ambiguity_across_m entries", d);
  requireNonNegative("ambiguity_separation_m", ambiguity_separation_m);
  requirePositive("ambiguity_rival_share", ambiguity_rival_share);
  requireRange("min_horizontal_conditioning", min_horizontal_conditioning, 0.0, 1.0);
  if (!std::isfinite(submap_agreement_m))
    rejectValue("submap_agreement_m", submap_agreement_m, "finite");
  if (!std::isfinite(max_correction_m)) rejectValue("max_correction_m", max_correction_m, "finite");
  requireNonNegative("correction_per_m", correction_per_m);
  if (!std::isfinite(consistency_m)) rejectValue("consistency_m", consistency_m, "finite");
  requireNonNegative("consistency_per_m", consistency_per_m);
  requireNonNegative("window_per_m", window_per_m);
  if (!(window_max_m >= radius_m && window_max_m <= 200))
    rejectValue("window_max_m", window_max_m, "in [radius_m, 200]");
  requireRange("correlative_yaw_deg", correlative_yaw_deg, 0.0, 90.0);
  requireNonNegative("correlative_separation_m", correlative_separation_m);
  if (!(correlative_max_ratio > 0 && correlative_max_ratio <= 1))
    rejectValue("correlative_max_ratio", correlative_max_ratio, "in (0, 1]");
  requirePositive("graph_odom_sigma_m", graph_odom_sigma_m);
  requirePositive("graph_odom_sigma_rad", graph_odom_sigma_rad);
  requirePositive("graph_loop_sigma_m", graph_loop_sigma_m);
  requirePositive("graph_loop_sigma_rad", graph_loop_sigma_rad);
  requireRange("graph_imu_pitch_sigma_deg", graph_imu_pitch_sigma_deg, 0.0, 10.0);
  requireRange("graph_pitch_bias_sigma_deg", graph_pitch_bias_sigma_deg, 0.0, 10.0);
  requireNonNegative("place_gate_per_m", place_gate_per_m);
  if (!(place_gate_max_m >= radius_m && std::isfinite(place_gate_max_m)))
    rejectValue("place_gate_max_m", place_gate_max_m, ">= radius_m");
  if (!(place_max_yaw_change_deg > 0 && place_max_yaw_change_deg <= 180))
    rejectValue("place_max_yaw_change_deg", place_max_yaw_change_deg, "in (0, 180]");
  config::validateSubsection("place.", place);
}

void OutputConfig::validate() const {
  requireRange("map_voxel_m", map_voxel_m, 0.01, 10.0);
  if (!(map_tile_m >= 10 && std::isfinite(map_tile_m)))
    rejectValue("map_tile_m", map_tile_m, ">= 10");
}

void MetricsConfig::validate() const {
  requirePositive("map_accuracy_max_m", map_accuracy_max_m);
  requirePositive("assoc_max_dt_s", assoc_max_dt_s);
  for (double l : rpe_lengths_m) requirePositive("rpe_lengths_m entries", l);
  requireNonNegative("rpe_segment_m", rpe_segment_m);
  requireRange("rpe_step_frames", rpe_step_frames, 1, kMaxCount);
  requireRange("plot_size_px", plot_size_px, 100, 8000);
}

void Config::validate() const {
  config::validateSubsection("input.", input);
  config::validateSubsection("features.", features);
  config::validateSubsection("odometry.", odometry);
  config::validateSubsection("mapping.", mapping);
  config::validateSubsection("relocalise.", relocalise);
  config::validateSubsection("loop.", loop);
  config::validateSubsection("output.", output);
  config::validateSubsection("metrics.", metrics);
}

}  // namespace slamroute::evaluate
