// validate() of the roadgraph config sections: values with which graph extraction cannot work
// (no intersection can be found, a loop never ends, a radius swallows everything).
#include "slamroute/core/ConfigCheck.hpp"
#include "slamroute/roadgraph/Config.hpp"

namespace slamroute::roadgraph {
using config::requireNonNegative;
using config::requirePositive;
using config::requireRange;

void NodeConfig::validate() const {
  requirePositive("downsample_m", downsample_m, 100.0);
  requirePositive("inner_radius_m", inner_radius_m, 1000.0);
  if (!(outer_radius_m > inner_radius_m && outer_radius_m <= 1000.0))
    config::rejectValue("outer_radius_m", outer_radius_m, "> inner_radius_m and <= 1000");
  requirePositive("height_m", height_m, 1000.0);
  requirePositive("cluster_tolerance_m", cluster_tolerance_m, 1000.0);
  requireRange("min_cluster_points", min_cluster_points, 1, 1000000);
  requireNonNegative("min_branch_span_m", min_branch_span_m, 1000.0);
  requireRange("min_branch_angle_deg", min_branch_angle_deg, 0.0, 180.0);
  requireRange("parallel_angle_deg", parallel_angle_deg, 0.0, 90.0);
  requireNonNegative("carriageway_gap_m", carriageway_gap_m, 1000.0);
  requireNonNegative("wide_scale", wide_scale, 10.0);
  requireRange("wide_min_coverage_deg", wide_min_coverage_deg, 0.0, 360.0);
  // Two branches are any point of a plain street: an intersection needs at least three.
  requireRange("min_branches", min_branches, 3, 16);
  requireRange("min_axis_coherence", min_axis_coherence, 0.0, 1.0);
  requirePositive("travel_span_m", travel_span_m, 1000.0);
  requireRange("vote_iterations", vote_iterations, 0, 100);
  requirePositive("vote_max_m", vote_max_m, 1000.0);
  requirePositive("vote_radius_m", vote_radius_m, 1000.0);
  requirePositive("node_radius_m", node_radius_m, 1000.0);
  requireNonNegative("merge_distance_m", merge_distance_m, 1000.0);
  requireNonNegative("min_vote_fraction", min_vote_fraction, 100.0);
  requireRange("min_node_points", min_node_points, 1, 1000000);
  requireNonNegative("strong_vote_factor", strong_vote_factor, 1000.0);
}

void EdgeConfig::validate() const {
  requirePositive("clear_radius_m", clear_radius_m, 1000.0);
  requirePositive("cluster_tolerance_m", cluster_tolerance_m, 1000.0);
  requireRange("min_street_points", min_street_points, 1, 1000000);
  requireNonNegative("attach_max_m", attach_max_m, 1000.0);
  requireNonNegative("end_merge_m", end_merge_m, 1000.0);
  requirePositive("polyline_step_m", polyline_step_m, 1000.0);
  requireNonNegative("centreline_branch_max_m", centreline_branch_max_m, 1e5);
  requireNonNegative("min_run_m", min_run_m, 1e5);
  requirePositive("max_gap_s", max_gap_s, 1e5);
  requireRange("min_direction_runs", min_direction_runs, 1, 1000000);
  requireNonNegative("stop_line_reach_m", stop_line_reach_m, 1000.0);
  requireNonNegative("bend_end_reach_m", bend_end_reach_m, 1000.0);
  requireNonNegative("link_visit_m", link_visit_m, 1000.0);
  requireNonNegative("link_max_m", link_max_m, 1000.0);
  requireRange("min_link_vehicles", min_link_vehicles, 1, 1000000);
}

void DividedRoadConfig::validate() const {
  requireNonNegative("max_node_gap_m", max_node_gap_m, 1000.0);
  requireNonNegative("min_offset_m", min_offset_m, 1000.0);
  requireNonNegative("max_along_m", max_along_m, 1000.0);
  requirePositive("arm_length_m", arm_length_m, 1000.0);
  requireNonNegative("parallel_angle_deg", parallel_angle_deg, 90.0);
  requireNonNegative("stagger_max_gap_m", stagger_max_gap_m, 1000.0);
  requireNonNegative("stagger_straight_deg", stagger_straight_deg, 90.0);
}

void DepthConfig::validate() const {
  requireRange("pixel_stride", pixel_stride, 1, 1000);
  // A surface normal is the plane through at least three points.
  requireRange("normal_neighbours", normal_neighbours, 3, 1000);
  requireRange("search_window_px", search_window_px, 1, 100);
  requirePositive("depth_px_per_m", depth_px_per_m, 1e6);
  requirePositive("max_depth_m", max_depth_m, 1e5);
  requireRange("min_normals", min_normals, 0, 100000000);
  requirePositive("frame_max_dist_m", frame_max_dist_m, 1e5);
  requireNonNegative("fallback_weight", fallback_weight, 1e6);
}

void SumoMatchConfig::validate() const {
  requirePositive("match_radius_m", match_radius_m, 1000.0);
  requirePositive("sample_step_m", sample_step_m, 1000.0);
  requirePositive("max_lane_dist_m", max_lane_dist_m, 1000.0);
  requireNonNegative("end_skip_m", end_skip_m, 1000.0);
  requireNonNegative("stray_radius_m", stray_radius_m, 1000.0);
  requireNonNegative("stray_min_length_m", stray_min_length_m, 1e5);
  requireNonNegative("connector_max_m", connector_max_m, 100.0);
  requireRange("bridged_end_max_samples", bridged_end_max_samples, 0, 1000);
  requireNonNegative("turn_max_detour_m", turn_max_detour_m, 1e5);
  requireNonNegative("place_link_max_m", place_link_max_m, 1000.0);
}

void RoundaboutConfig::validate() const {
  requirePositive("min_radius_m", min_radius_m, 1000.0);
  if (!(max_radius_m >= min_radius_m && max_radius_m <= 1000.0))
    config::rejectValue("max_radius_m", max_radius_m, ">= min_radius_m and <= 1000");
  requirePositive("resample_m", resample_m, 1000.0);
  requireRange("min_sweep_deg", min_sweep_deg, 1.0, 3600.0);
  requirePositive("max_fit_rms_m", max_fit_rms_m, 1000.0);
  requirePositive("centre_tolerance_m", centre_tolerance_m, 1000.0);
  requireRange("min_vehicles", min_vehicles, 1, 1000000);
  requirePositive("ring_width_m", ring_width_m, 1000.0);
  requireRange("min_occupied", min_occupied, 0.0, 1.0);
  requireRange("min_sense_share", min_sense_share, 0.0, 1.0);
  requireNonNegative("max_inner_share", max_inner_share, 1e6);
  requirePositive("join_width_m", join_width_m, 1000.0);
  requireNonNegative("min_run_sweep_deg", min_run_sweep_deg, 3600.0);
  requirePositive("arm_gap_m", arm_gap_m, 1000.0);
  requireRange("min_arm_vehicles", min_arm_vehicles, 1, 1000000);
  requireNonNegative("junction_merge_m", junction_merge_m, 1000.0);
  requireNonNegative("absorb_margin_m", absorb_margin_m, 1000.0);
}

}  // namespace slamroute::roadgraph
