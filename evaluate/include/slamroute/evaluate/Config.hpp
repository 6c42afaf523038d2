#pragma once
// Parameters of the evaluate module (paper §3.3: LeGO-LOAM odometry + mapping + loop closure and
// the trajectory / map metrics). Defaults follow LeGO-LOAM (Shan & Englot 2018) where the paper
// is silent. YAML section "evaluate:".
#include <string>
#include <vector>

namespace slamroute::evaluate {

struct Config {
  /// Use every n-th scan of the drive (1 = all, 10 Hz). 2 (5 Hz) halves the SLAM time; the
  /// constant-velocity prediction bridges the ~2.5 m between scans at city speed. On the noisy
  /// 1.77 km vlp16 drive (bench/RESULTS.md "Odometry") stride 2 gave ATE 0.083 m, stride 1 0.088 m.
  int scan_stride = 2;
  /// ... but every scan while the estimated turn rate exceeds this (0 = never) [deg/s]. SUMO
  /// drives U-turns at up to ~90 deg/s; at 5 Hz that is 18 deg between scans, beyond the reach
  /// of local registration.
  double dense_turn_rate_deg_s = 10.0;
  double dense_after_failure_s = 1.0;  ///< ... and for this long after a failed scan [s]
  double start_s = 0.0;  ///< evaluate only scans from this drive time on [s]
  double end_s = 0.0;    ///< ... up to this drive time; 0 = to the end [s]
  // --- range image (LeGO-LOAM "imageProjection") ---
  bool use_ring_field = true;        ///< use ScanPoint.ring when >= 0, else ring from elevation
  bool ring_zero_is_bottom = true;   ///< ring 0 is the lowest beam (KITTI/Velodyne order)
  double min_range_m = 1.0;          ///< points closer than this are dropped [m]
  // --- ground segmentation ---
  double ground_max_elevation_deg = -1.0;  ///< only beams below this elevation can be ground [deg]
  double ground_angle_deg = 10.0;    ///< max slope between vertically adjacent points [deg]
  double sensor_mount_angle_deg = 0.0;  ///< sensor pitch on the vehicle [deg]
  // --- range-image clustering ---
  double segment_theta_deg = 60.0;   ///< BFS joins neighbours whose beta angle exceeds this [deg]
  int min_cluster_points = 30;       ///< clusters at least this big are kept
  int min_line_cluster_points = 5;   ///< ... or at least this big spanning min_cluster_rings rings
  int min_cluster_rings = 3;         ///< rings a small (pole-like) cluster must span
  int ground_column_stride = 5;      ///< keep every n-th ground point for features (LeGO: 5)
  // --- features (LeGO-LOAM "featureAssociation") ---
  int feature_sectors = 6;           ///< sectors per ring
  int curvature_half_window = 5;     ///< neighbours on each side for the curvature
  double edge_curvature = 0.1;       ///< curvature above this: edge candidate
  double surf_curvature = 0.1;       ///< curvature below this: planar candidate
  int sharp_per_sector = 2;          ///< sharpest points per sector (scan-to-scan source)
  int less_sharp_per_sector = 20;    ///< edge points per sector (map / scan-to-scan target)
  int flat_per_sector = 4;           ///< flattest ground points per sector (scan-to-scan source)
  double occlusion_gap_m = 0.3;      ///< range jump marking occluded neighbours [m]
  double less_flat_voxel_m = 0.4;    ///< voxel size for the less-flat cloud [m]
  // --- scan-to-scan odometry ---
  bool two_step_odometry = true;     ///< planar -> z/roll/pitch, then edges -> x/y/yaw (LeGO)
  int odom_iterations = 15;          ///< Gauss-Newton iterations per step
  double odom_max_nn_m = 1.5;        ///< correspondence search radius scan-to-scan [m]
  // --- scan-to-map ---
  int map_iterations = 10;           ///< Gauss-Newton iterations scan-to-map
  int map_reassociate_every = 2;     ///< scan-to-map: new neighbours / line and plane fits every
                                     ///< n-th iteration, fixed in between (1 = every iteration)
  double map_max_nn_m = 1.0;         ///< correspondence search radius scan-to-map [m]
  double map_edge_voxel_m = 0.2;     ///< voxel for edge features (source and local map) [m]
  double map_surf_voxel_m = 0.4;     ///< voxel for planar features (source and local map) [m]
  int map_max_source_edges = 3000;   ///< edge features per scan used for mapping (strided)
  int map_max_source_planes = 6000;  ///< planar features per scan used for mapping (strided)
  /// Rebuild the local map after this much motion [m]. 3 m: 11 % less time per scan, but the
  /// `run` qlearning drive's ATE went 0.78 -> 0.87 m (bench/RESULTS.md), so it stays at 2 m.
  double local_map_update_m = 2.0;
  double keyframe_distance_m = 1.0; ///< new keyframe after this much motion [m]
  double keyframe_angle_deg = 10.0;  ///< ... or this much rotation [deg]
  int local_map_keyframes = 40;      ///< recent keyframes in the local map
  double local_map_radius_m = 60.0;  ///< and only those within this radius [m]
  double huber_m = 0.02;             ///< robust (Huber) kernel width for residuals [m]. Not in
                                     ///< LeGO-LOAM (it uses 1-0.9|d|); 2 cm cut the ATE of a
                                     ///< 400-scan default-city drive from 0.062 to 0.022 m
  double plane_max_dev_m = 0.2;      ///< plane fit: all 5 neighbours within this [m] (LOAM 0.2)
  // --- reliability ---
  int min_valid_points = 500;        ///< fewer valid points: the scan is unusable
  int min_edge_features = 10;        ///< fewer edge matches: unreliable
  int min_plane_features = 50;       ///< fewer plane matches: unreliable
  double degeneracy_min_eig = 0.02;  ///< min normalised eigenvalue of the translation block
  bool degeneracy_remap = false;     ///< freeze degenerate directions in scan-to-map (LOAM);
                                     ///< off: on the noisy default-city drive it made drift worse
  double max_step_change_m = 2.0;    ///< odometry/mapping may change the prediction by at most [m]
  double max_step_change_deg = 10.0; ///< ... and [deg] per 0.1 s; larger: rejected as a failure
  /// Car dynamics: the turn rate is at most this over the speed (6 m/s^2: 25 deg/s at 50 km/h).
  /// A registration turning further from the prediction is rejected: at 5 Hz a car passing 3 m
  /// away pulled the scan-to-map 14 deg off on a straight street. 0 = off [m/s^2]
  double max_lateral_accel_mps2 = 6.0;
  double rotation_slack_deg = 1.5;   ///< allowed on top of the dynamic bound per scan [deg]
  /// With wheel odometry + gyro: a registration may move the odometry's prediction at most this
  /// far in x/y and yaw per 0.1 s (the gyro drifts ~0.05 deg/s, the wheels ~1 %) [m], [deg]
  double odometry_translation_slack_m = 0.25;
  double odometry_rotation_slack_deg = 0.5;
  /// With wheel odometry + gyro: the scan-to-map also pulls towards the odometry's prediction
  /// with these sigmas per 0.1 s, against LiDAR residuals of `registration_sigma_m` (a prior
  /// factor, as in LiDAR-inertial smoothers; 0 = off). It decides only the directions the
  /// features leave weak: yaw on an open street with a pole or two. `run` qlearning drive
  /// (14.4 km): ATE 1.03 m without, 0.72 m with the yaw prior 0.02 deg, 1.08 m with the x/y prior
  /// 0.02 m as well (a simulated car also slips sideways in turns, the wheels do not see it) [m], [deg]
  double odometry_prior_sigma_m = 0.0;
  double odometry_prior_sigma_deg = 0.02;
  /// The sigma above was tuned for the simulated default gyro (white noise 0.1 deg/s, bias
  /// 0.05 deg/s). When the drive states its gyro's figures (odometry.yaml), the sigma scales
  /// with them: x sqrt(noise^2 + bias^2) / sqrt(ref_noise^2 + ref_bias^2), at least
  /// odometry_prior_min_sigma_deg (a noise-free gyro; a fibre-optic gyro's 0.1 s random walk is
  /// ~0.0001 deg). Noise-free route1k drive (bench/RESULTS.md): ATE 0.132 m with 0.02 deg, 0.091 m
  /// with 0.0002 deg. Reference 0 = always odometry_prior_sigma_deg [deg/s], [deg]
  double odometry_prior_ref_noise_deg_s = 0.1;
  double odometry_prior_ref_bias_deg_s = 0.05;
  double odometry_prior_min_sigma_deg = 0.0002;
  double registration_sigma_m = 0.05;
  /// With IMU roll / pitch in odometry.csv: after each scan the pose's roll and pitch move this
  /// share of the way to the IMU's (LeGO-LOAM blends 0.002 per scan at 10 Hz; 0 = off). On the
  /// `run` qlearning drive (14.4 km) the pitch was 2 deg off after the overpass ramp for good and
  /// the height wandered 20 m: ATE 9.35 m without, 3.55 m with 0.01, 1.03 m with 0.2.
  double imu_tilt_weight = 0.2;
  double failed_turn_decay = 0.9;    ///< a failed scan keeps the speed, the turn rate times this
  // --- relocalisation (not in LeGO-LOAM) ---
  // Simulated drives have heading jumps of up to ~100 deg within one scan where SUMO switches a
  // vehicle onto a junction's internal lane. Local registration cannot converge from there; a
  // failed scan-to-map (few matches or an implausible jump) then tries yaw hypotheses around the
  // prediction and keeps the one with the most inliers.
  double map_coarse_nn_m = 3.0;         ///< > 0: coarse scan-to-map stage with this radius first
                                        ///< (not in LeGO-LOAM; stride-2 turns need it) [m]
  bool use_odometry = true;             ///< predict with the drive's odometry.csv when it has one
  /// Gyro bias from the stops of the drive (core removeStandstillGyroBias): wheel speed below
  /// this counts as standstill (3 sigma of the simulated wheel-speed noise); 0 = keep the gyro
  /// as recorded [m/s].
  double gyro_standstill_mps = 0.15;
  double gyro_min_standstill_s = 2.0;   ///< standstill needed before the bias is trusted [s]
  double gyro_standstill_margin_s = 0.6;  ///< ... counted only this long after / before motion [s]
  bool relocalize = true;               ///< yaw search when scan-to-map fails
  double relocalize_inlier_drop = 0.5;  ///< ... or when the inliers fall below this share of
                                        ///< the recent inlier level
  double relocalize_ref_decay = 0.8;    ///< the recent level decays by this per scan
  double relocalize_yaw_step_deg = 15.0;  ///< spacing of the yaw hypotheses over 360 deg [deg]
  int relocalize_iterations = 6;        ///< Gauss-Newton iterations per hypothesis
  int relocalize_max_points = 1500;     ///< source features per hypothesis (strided)
  double failed_keyframe_distance_m = 5.0;  ///< failed scans become keyframes only this far
                                            ///< from the last keyframe (keeps the map clean) [m]
  // --- loop closure + pose graph ---
  bool loop_closure = true;          ///< enable ICP loop closure
  double loop_radius_m = 7.0;        ///< search radius around the new keyframe [m]
  double loop_min_time_gap_s = 30.0; ///< candidate must be older than this [s]
  int loop_submap_keyframes = 10;    ///< keyframes each side of the candidate in its submap
  double loop_voxel_m = 0.4;         ///< voxel for ICP clouds [m]
  int loop_icp_iterations = 30;      ///< point-to-plane ICP iterations
  double loop_icp_max_corr_m = 2.0;  ///< ICP correspondence distance (shrinks to a third) [m]
  double loop_fitness_m2 = 0.09;     ///< accept if mean squared inlier distance below [m^2]
  double loop_min_inlier_ratio = 0.5;  ///< ... and at least this share of points matched
  double loop_cooldown_s = 5.0;      ///< min time between two accepted closures [s]
  /// Local-minimum check (not in LeGO-LOAM): an accepted ICP match is run again from its result
  /// shifted by these offsets along and across the new keyframe's heading (both signs). When one
  /// of them ends on another pose, more than loop_ambiguity_separation_m away, that passes the
  /// same test and fits better (lower fitness, at least loop_ambiguity_inlier_margin more of the
  /// points matched), the first match stopped in a local minimum, e.g. one facade along a row of
  /// look-alike facades: the closure is refused and the next keyframe tries again. On the false
  /// closures of `experiment paper` the better pose found this way was the true one. Empty = off [m]
  std::vector<double> loop_ambiguity_along_m = {3, 6, 9, 12};
  std::vector<double> loop_ambiguity_across_m = {3, 6};
  double loop_ambiguity_separation_m = 1.5;
  double loop_ambiguity_inlier_margin = 0.0;
  /// A closure may move the new keyframe at most loop_max_correction_m plus
  /// loop_correction_per_m times the distance driven since the last accepted closure (the drift
  /// the odometry can have gathered since); a larger jump is taken for a look-alike place.
  /// Offline on the 1,314 closures of `experiment paper` (commit 6b7e713): 1 m + 0.2 % would have
  /// rejected 50 of the 75 false and 56 of the 1,239 true ones. Off by default: on the `run`
  /// drives it gave ATE 6.59 / 1.48 / 3.61 m (qlearning / random / postman) against 0.72 / 0.72 /
  /// 7.15 m without: refusing true closures leaves the drift in place. Negative = no bound [m], [m/m]
  double loop_max_correction_m = -1.0;
  double loop_correction_per_m = 0.002;
  double graph_odom_sigma_m = 0.05;  ///< pose-graph odometry edge sigma (translation) [m]
  double graph_odom_sigma_rad = 0.005;  ///< pose-graph odometry edge sigma (rotation) [rad]
  double graph_loop_sigma_m = 0.1;   ///< loop edge sigma (translation) [m]
  double graph_loop_sigma_rad = 0.01;   ///< loop edge sigma (rotation) [rad]
  // --- map output + accuracy ---
  double map_voxel_m = 0.2;          ///< voxel of map.pcd [m]
  /// The map is merged and written in square tiles of this size (MapTiles.hpp), so the merge
  /// holds one tile's voxels, not the whole map's; a keyframe's cloud (100 m range) is read once
  /// per tile it overlaps. Same map points for any size [m].
  double map_tile_m = 400.0;
  /// Keyframe clouds in an unnamed file in the output folder instead of memory: same results,
  /// resident memory no longer grows by ~47 kB per keyframe (bench/RESULTS.md "Memory of a SLAM
  /// run"); the file takes that much disk until the run ends.
  bool keyframe_clouds_on_disk = true;
  double map_accuracy_max_m = 2.0;   ///< distances are clamped here (points off the world) [m]
  // --- metrics ---
  double assoc_max_dt_s = 0.02;      ///< timestamp association tolerance [s]
  std::vector<double> rpe_lengths_m = {100, 200, 300, 400, 500, 600, 700, 800};  ///< KITTI [m]
  double rpe_segment_m = 50.0;       ///< extra user segment length for RPE [m]
  int rpe_step_frames = 10;          ///< start a segment every n frames (KITTI: 10)
  int plot_size_px = 1000;           ///< plot width and height [px]
};

template <class V>
void visitFields(V& v, Config& c) {
  v.field("scan_stride", c.scan_stride, "use every n-th scan (1 = all, 10 Hz)");
  v.field("use_odometry", c.use_odometry,
          "predict the motion between scans from the drive's wheel odometry + gyro (odometry.csv) if present");
  v.field("gyro_standstill_mps", c.gyro_standstill_mps,
          "gyro bias from the drive's stops: speed below this is standstill, 0 = off [m/s]");
  v.field("gyro_min_standstill_s", c.gyro_min_standstill_s, "standstill needed before the bias is used [s]");
  v.field("gyro_standstill_margin_s", c.gyro_standstill_margin_s,
          "standstill counts only this long after stopping and before starting [s]");
  v.field("dense_turn_rate_deg_s", c.dense_turn_rate_deg_s, "every scan above this turn rate, 0 = off [deg/s]");
  v.field("dense_after_failure_s", c.dense_after_failure_s, "every scan this long after a failure [s]");
  v.field("start_s", c.start_s, "evaluate scans from this drive time on [s]");
  v.field("end_s", c.end_s, "evaluate scans up to this drive time, 0 = to the end [s]");
  v.field("use_ring_field", c.use_ring_field, "use ScanPoint.ring when >= 0");
  v.field("ring_zero_is_bottom", c.ring_zero_is_bottom, "ring 0 is the lowest beam");
  v.field("min_range_m", c.min_range_m, "points closer are dropped [m]");
  v.field("ground_max_elevation_deg", c.ground_max_elevation_deg, "beams below can be ground [deg]");
  v.field("ground_angle_deg", c.ground_angle_deg, "max slope between adjacent ground points [deg]");
  v.field("sensor_mount_angle_deg", c.sensor_mount_angle_deg, "sensor pitch [deg]");
  v.field("segment_theta_deg", c.segment_theta_deg, "clustering angle threshold [deg]");
  v.field("min_cluster_points", c.min_cluster_points, "min points of a kept cluster");
  v.field("min_line_cluster_points", c.min_line_cluster_points, "min points of a thin cluster");
  v.field("min_cluster_rings", c.min_cluster_rings, "rings a thin cluster must span");
  v.field("ground_column_stride", c.ground_column_stride, "keep every n-th ground point");
  v.field("feature_sectors", c.feature_sectors, "sectors per ring");
  v.field("curvature_half_window", c.curvature_half_window, "curvature neighbours per side");
  v.field("edge_curvature", c.edge_curvature, "edge curvature threshold");
  v.field("surf_curvature", c.surf_curvature, "planar curvature threshold");
  v.field("sharp_per_sector", c.sharp_per_sector, "sharp points per sector");
  v.field("less_sharp_per_sector", c.less_sharp_per_sector, "less-sharp points per sector");
  v.field("flat_per_sector", c.flat_per_sector, "flat points per sector");
  v.field("occlusion_gap_m", c.occlusion_gap_m, "occlusion range jump [m]");
  v.field("less_flat_voxel_m", c.less_flat_voxel_m, "less-flat voxel [m]");
  v.field("two_step_odometry", c.two_step_odometry, "LeGO two-step scan-to-scan");
  v.field("odom_iterations", c.odom_iterations, "scan-to-scan iterations per step");
  v.field("odom_max_nn_m", c.odom_max_nn_m, "scan-to-scan correspondence radius [m]");
  v.field("map_iterations", c.map_iterations, "scan-to-map iterations");
  v.field("map_reassociate_every", c.map_reassociate_every, "scan-to-map: new correspondences every n-th iteration");
  v.field("map_max_nn_m", c.map_max_nn_m, "scan-to-map correspondence radius [m]");
  v.field("map_edge_voxel_m", c.map_edge_voxel_m, "edge voxel [m]");
  v.field("map_surf_voxel_m", c.map_surf_voxel_m, "planar voxel [m]");
  v.field("map_max_source_edges", c.map_max_source_edges, "edge features per scan for mapping");
  v.field("map_max_source_planes", c.map_max_source_planes, "planar features per scan for mapping");
  v.field("local_map_update_m", c.local_map_update_m, "local map rebuild distance [m]");
  v.field("keyframe_distance_m", c.keyframe_distance_m, "keyframe spacing [m]");
  v.field("keyframe_angle_deg", c.keyframe_angle_deg, "keyframe rotation [deg]");
  v.field("local_map_keyframes", c.local_map_keyframes, "keyframes in the local map");
  v.field("local_map_radius_m", c.local_map_radius_m, "local map radius [m]");
  v.field("huber_m", c.huber_m, "robust kernel width [m]");
  v.field("plane_max_dev_m", c.plane_max_dev_m, "plane fit max neighbour deviation [m]");
  v.field("min_valid_points", c.min_valid_points, "min valid points per scan");
  v.field("min_edge_features", c.min_edge_features, "min edge matches");
  v.field("min_plane_features", c.min_plane_features, "min plane matches");
  v.field("degeneracy_min_eig", c.degeneracy_min_eig, "min normalised translation eigenvalue");
  v.field("degeneracy_remap", c.degeneracy_remap, "freeze degenerate directions");
  v.field("max_step_change_m", c.max_step_change_m, "max change of the prediction per scan [m]");
  v.field("max_step_change_deg", c.max_step_change_deg, "max change of the prediction per scan [deg]");
  v.field("max_lateral_accel_mps2", c.max_lateral_accel_mps2, "turn rate bound: this over the speed, 0 = off [m/s^2]");
  v.field("rotation_slack_deg", c.rotation_slack_deg, "rotation allowed on top of the bound per scan [deg]");
  v.field("odometry_translation_slack_m", c.odometry_translation_slack_m,
          "with wheel odometry: registration may move its prediction this far per 0.1 s [m]");
  v.field("odometry_rotation_slack_deg", c.odometry_rotation_slack_deg,
          "with wheel odometry: ... and turn it this much in yaw per 0.1 s [deg]");
  v.field("odometry_prior_sigma_m", c.odometry_prior_sigma_m,
          "scan-to-map prior towards the odometry, x/y sigma per 0.1 s (0 = off) [m]");
  v.field("odometry_prior_sigma_deg", c.odometry_prior_sigma_deg,
          "scan-to-map prior towards the odometry, yaw sigma per 0.1 s (0 = off) [deg]");
  v.field("odometry_prior_ref_noise_deg_s", c.odometry_prior_ref_noise_deg_s,
          "gyro white noise the yaw sigma is tuned for; a drive's odometry.yaml scales it, 0 = off [deg/s]");
  v.field("odometry_prior_ref_bias_deg_s", c.odometry_prior_ref_bias_deg_s, "... and gyro bias [deg/s]");
  v.field("odometry_prior_min_sigma_deg", c.odometry_prior_min_sigma_deg,
          "... but at least this (a noise-free gyro) [deg]");
  v.field("registration_sigma_m", c.registration_sigma_m, "LiDAR residual sigma for the odometry prior [m]");
  v.field("imu_tilt_weight", c.imu_tilt_weight,
          "share of the way roll/pitch move to the IMU's after each scan (odometry.csv with roll/pitch), 0 = off");
  v.field("failed_turn_decay", c.failed_turn_decay, "turn rate kept per failed scan (share)");
  v.field("map_coarse_nn_m", c.map_coarse_nn_m, "coarse scan-to-map radius, 0 = off [m]");
  v.field("relocalize", c.relocalize, "yaw search when scan-to-map fails");
  v.field("relocalize_inlier_drop", c.relocalize_inlier_drop, "inlier drop share triggering the search");
  v.field("relocalize_ref_decay", c.relocalize_ref_decay, "decay of the recent inlier level per scan");
  v.field("relocalize_yaw_step_deg", c.relocalize_yaw_step_deg, "yaw hypothesis spacing [deg]");
  v.field("relocalize_iterations", c.relocalize_iterations, "iterations per yaw hypothesis");
  v.field("relocalize_max_points", c.relocalize_max_points, "source features per hypothesis");
  v.field("failed_keyframe_distance_m", c.failed_keyframe_distance_m, "keyframe distance of failed scans [m]");
  v.field("loop_closure", c.loop_closure, "enable loop closure");
  v.field("loop_radius_m", c.loop_radius_m, "loop search radius [m]");
  v.field("loop_min_time_gap_s", c.loop_min_time_gap_s, "loop min time gap [s]");
  v.field("loop_submap_keyframes", c.loop_submap_keyframes, "submap keyframes each side");
  v.field("loop_voxel_m", c.loop_voxel_m, "ICP voxel [m]");
  v.field("loop_icp_iterations", c.loop_icp_iterations, "ICP iterations");
  v.field("loop_icp_max_corr_m", c.loop_icp_max_corr_m, "ICP correspondence distance [m]");
  v.field("loop_fitness_m2", c.loop_fitness_m2, "ICP fitness threshold [m^2]");
  v.field("loop_min_inlier_ratio", c.loop_min_inlier_ratio, "ICP min inlier share");
  v.field("loop_cooldown_s", c.loop_cooldown_s, "min time between closures [s]");
  v.field("loop_ambiguity_along_m", c.loop_ambiguity_along_m,
          "loop closure refused when ICP from these offsets along the heading finds a better match, [] = off [m]");
  v.field("loop_ambiguity_across_m", c.loop_ambiguity_across_m, "... and across it [m]");
  v.field("loop_ambiguity_separation_m", c.loop_ambiguity_separation_m,
          "... at least this far from the first one [m]");
  v.field("loop_ambiguity_inlier_margin", c.loop_ambiguity_inlier_margin,
          "... matching this much larger a share of the points (and with a lower fitness)");
  v.field("loop_max_correction_m", c.loop_max_correction_m,
          "max jump of a loop closure right after another one (negative = no bound) [m]");
  v.field("loop_correction_per_m", c.loop_correction_per_m,
          "... plus this per metre driven since the last closure [m/m]");
  v.field("graph_odom_sigma_m", c.graph_odom_sigma_m, "odometry edge sigma [m]");
  v.field("graph_odom_sigma_rad", c.graph_odom_sigma_rad, "odometry edge sigma [rad]");
  v.field("graph_loop_sigma_m", c.graph_loop_sigma_m, "loop edge sigma [m]");
  v.field("graph_loop_sigma_rad", c.graph_loop_sigma_rad, "loop edge sigma [rad]");
  v.field("map_voxel_m", c.map_voxel_m, "map.pcd voxel [m]");
  v.field("map_tile_m", c.map_tile_m, "map merged in tiles of this size [m]");
  v.field("keyframe_clouds_on_disk", c.keyframe_clouds_on_disk, "keyframe clouds in a temporary file, not memory");
  v.field("map_accuracy_max_m", c.map_accuracy_max_m, "map distance clamp [m]");
  v.field("assoc_max_dt_s", c.assoc_max_dt_s, "timestamp association tolerance [s]");
  v.field("rpe_lengths_m", c.rpe_lengths_m, "KITTI RPE segment lengths [m]");
  v.field("rpe_segment_m", c.rpe_segment_m, "user RPE segment length [m]");
  v.field("rpe_step_frames", c.rpe_step_frames, "RPE start stride [frames]");
  v.field("plot_size_px", c.plot_size_px, "plot size [px]");
}

}  // namespace slamroute::evaluate
