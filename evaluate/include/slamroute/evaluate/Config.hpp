#pragma once
// Parameters of the evaluate module (paper §3.3: LeGO-LOAM odometry + mapping + loop closure and
// the trajectory / map metrics), one section per part of the SLAM (evaluate/src/slam/). Defaults
// follow LeGO-LOAM (Shan & Englot 2018) where the paper is silent. YAML section "evaluate:".
// Figures quoted below come from bench/RESULTS.md.
#include <string>
#include <vector>

#include "slamroute/evaluate/PlaceRecognitionConfig.hpp"

namespace slamroute::evaluate {

/// Which scans of the drive are used.
struct InputConfig {
  void validate() const;  ///< values that cannot work: std::invalid_argument (Config.cpp)
  /// Use every n-th scan of the drive (1 = all, 10 Hz); 2 halves the SLAM time and the
  /// prediction bridges the ~2.5 m between scans at city speed.
  int scan_stride = 2;
  /// ... but every scan while the estimated turn rate exceeds this (0 = never) [deg/s]: SUMO
  /// drives U-turns at up to ~90 deg/s, 18 deg between scans at 5 Hz, beyond local registration.
  double dense_turn_rate_deg_s = 10.0;
  double dense_after_failure_s = 1.0;  ///< ... and for this long after a failed scan [s]
  double start_s = 0.0;                ///< evaluate only scans from this drive time on [s]
  double end_s = 0.0;                  ///< ... up to this drive time; 0 = to the end [s]
};

/// Range image, ground segmentation, clustering and features (LeGO-LOAM "imageProjection" and
/// "featureAssociation"), and motion compensation of the sweep.
struct FeaturesConfig {
  void validate() const;  ///< values that cannot work: std::invalid_argument (Config.cpp)
  /// Move every point to the sweep's start with the predicted motion over the sweep, when the
  /// scan carries point times (a spinning LiDAR fires its columns over 0.1 s while driving).
  bool deskew = true;
  /// Without wheel odometry the sweep's motion is the mean velocity of this many registrations
  /// (1: the last one's).
  int deskew_increments = 2;
  /// Without wheel odometry, register the sweep once, deskew it again with the step that ends at
  /// it (last registered scan to this one) and register that: the mean of earlier steps lags the
  /// sweep by ~0.25 s, and speed changes in between leave it stretched or squeezed. Off by
  /// default: on route1k it halves the LiDAR-only ATE, but at 1.6 x the SLAM time, and on a
  /// test-grid drive it lost the heading in a turn (bench/RESULTS.md, "The ruler").
  bool redeskew_without_odometry = false;
  bool use_ring_field = true;       ///< use ScanPoint.ring when >= 0, else ring from elevation
  bool ring_zero_is_bottom = true;  ///< ring 0 is the lowest beam (KITTI/Velodyne order)
  double min_range_m = 1.0;         ///< points closer than this are dropped [m]
  int min_valid_points = 500;       ///< fewer valid points: the scan is unusable
  double ground_max_elevation_deg = -1.0;  ///< only beams below this elevation can be ground [deg]
  double ground_angle_deg = 10.0;          ///< max slope between vertically adjacent points [deg]
  double sensor_mount_angle_deg = 0.0;     ///< sensor pitch on the vehicle [deg]
  double segment_theta_deg = 60.0;  ///< BFS joins neighbours whose beta angle exceeds this [deg]
  int min_cluster_points = 30;      ///< clusters at least this big are kept
  int min_line_cluster_points = 5;  ///< ... or at least this big spanning min_cluster_rings rings
  int min_cluster_rings = 3;        ///< rings a small (pole-like) cluster must span
  int ground_column_stride = 5;     ///< keep every n-th ground point for features (LeGO: 5)
  int feature_sectors = 6;          ///< sectors per ring
  int curvature_half_window = 5;    ///< neighbours on each side for the curvature
  double edge_curvature = 0.1;      ///< curvature above this: edge candidate
  double surf_curvature = 0.1;      ///< curvature below this: planar candidate
  int sharp_per_sector = 2;         ///< sharpest points per sector (scan-to-scan source)
  int less_sharp_per_sector = 20;   ///< edge points per sector (map / scan-to-scan target)
  int flat_per_sector = 4;          ///< flattest ground points per sector (scan-to-scan source)
  double occlusion_gap_m = 0.3;     ///< range jump marking occluded neighbours [m]
  double less_flat_voxel_m = 0.4;   ///< voxel size for the less-flat cloud [m]
};

/// The motion model: prediction between scans (wheel odometry + gyro, or constant velocity),
/// scan-to-scan registration and the bounds a registration is checked against.
struct OdometryConfig {
  void validate() const;           ///< values that cannot work: std::invalid_argument (Config.cpp)
  bool use_wheel_odometry = true;  ///< predict with the drive's odometry.csv when it has one
  /// Gyro bias from the drive's stops (core removeStandstillGyroBias): wheel speed below this
  /// is standstill (3 sigma of the simulated wheel-speed noise); 0 = keep the gyro as recorded.
  double gyro_standstill_mps = 0.15;
  double gyro_min_standstill_s = 2.0;     ///< standstill needed before the bias is trusted [s]
  double gyro_standstill_margin_s = 0.6;  ///< ... counted only this long after / before motion [s]
  bool two_step = true;                   ///< planar -> z/roll/pitch, then edges -> x/y/yaw (LeGO)
  int iterations = 15;                    ///< scan-to-scan Gauss-Newton iterations per step
  double max_nn_m = 1.5;                  ///< scan-to-scan correspondence radius [m]
  double max_step_change_m = 2.0;         ///< a registration may move the prediction at most [m]
  double max_step_change_deg = 10.0;      ///< ... and [deg] per 0.1 s; larger: a failure
  /// Car dynamics: the turn rate is at most this over the speed (6 m/s^2: 25 deg/s at 50 km/h);
  /// a registration turning further from the prediction is a failure (a passing car pulled a
  /// scan 14 deg off on a straight street). 0 = off [m/s^2]
  double max_lateral_accel_mps2 = 6.0;
  double rotation_slack_deg = 1.5;  ///< allowed on top of the dynamic bound per scan [deg]
  /// With wheel odometry + gyro a registration may move the odometry's prediction at most this
  /// far in x/y and yaw per 0.1 s (the gyro drifts ~0.05 deg/s, the wheels ~1 %) [m], [deg]
  double wheel_translation_slack_m = 0.25;
  double wheel_rotation_slack_deg = 0.5;
  /// After scans that failed to register the prediction has gone on from an uncorrected pose, so
  /// the slack counts the time since the last registered scan, up to this much more than the
  /// step: otherwise one registration just beyond the slack (a car slipping sideways in a U-turn)
  /// makes every following one fall further outside it. 0 = the step alone [s]
  double slack_since_fix_max_s = 1.0;
  /// With wheel odometry + gyro the scan-to-map also pulls towards the odometry's prediction
  /// with these sigmas per 0.1 s against LiDAR residuals of prior_registration_sigma_m (a prior
  /// factor, as in LiDAR-inertial smoothers; 0 = off). It decides only the directions the
  /// features leave weak, e.g. yaw on an open street. No x/y prior by default: a simulated car
  /// slips sideways in turns and the wheels do not see it. Along the heading the wheels are
  /// trusted (prior_along_sigma_m) where the scan says little that way: on a bridge deck the
  /// scan-to-map otherwise slides along the street [m], [deg]
  double prior_sigma_m = 0.0;
  double prior_along_sigma_m = 0.005;
  /// The along prior fades out as the scan's own information along the heading (per residual)
  /// rises to this: 0.05 keeps it on a bridge deck (0.015-0.02) and off in a street with posts
  /// and doors (0.1-0.3). It fades the whole prior on x, prior_sigma_m's share too. 0 = always on
  double prior_along_fade_info = 0.05;
  /// Without wheel odometry the constant-velocity prediction can take the wheels' place along
  /// the heading, with this sigma per 0.1 s (0.002 holds a bridge deck), fading out as the scan's
  /// information along the heading rises to velocity_prior_fade_info. On a bridge deck between
  /// uniform parapets the scan-to-map otherwise holds the car where the local map was built (the
  /// default city's deck: 230 m lost in 15 s). Off by default: a constant velocity misses the
  /// speed changes the LiDAR cannot see either, and an open street is as weak along the heading
  /// as a deck (a test-grid drive speeding up on its last street: 3.9 m with it, 1.9 m without;
  /// bench/RESULTS.md "The ruler"). 0 = off [m]
  double velocity_prior_along_sigma_m = 0.0;
  double velocity_prior_fade_info = 0.03;
  /// Without wheel odometry the constant-velocity prediction's yaw is a prior as well, with this
  /// sigma per 0.1 s, fading out as the scan's own yaw information (per residual) rises to
  /// velocity_prior_yaw_fade_info. Where a turn ends onto a street that holds little in yaw, one
  /// registration can otherwise turn the car by degrees where it turns none: route1k's VLP-16
  /// turned 5 deg at the end of the turn onto its open street, where the information is 1.4-10
  /// for 1.6 s (17-277 on all other scans, half above 99). A fade of 15 held that turn as well;
  /// 30 also held the test grid's open streets better (bench/RESULTS.md "The ruler"). The
  /// 64-channel scans of route1k hardly ever come below it. 0 = off [deg]
  double velocity_prior_yaw_sigma_deg = 0.1;
  double velocity_prior_yaw_fade_info = 30.0;
  double prior_sigma_deg = 0.02;
  /// prior_sigma_deg is tuned for the simulated default gyro (white noise 0.1 deg/s, bias
  /// 0.05 deg/s); a drive that states its gyro's figures (odometry.yaml) scales it by
  /// sqrt(noise^2 + bias^2) / sqrt(ref_noise^2 + ref_bias^2), at least prior_min_sigma_deg.
  /// Reference 0 = always prior_sigma_deg [deg/s], [deg]
  double prior_ref_noise_deg_s = 0.1;
  double prior_ref_bias_deg_s = 0.05;
  double prior_min_sigma_deg = 0.0002;
  double prior_registration_sigma_m = 0.05;
  /// Wheel scale measured by the LiDAR (slam/WheelScale): the ratio of registered to wheel
  /// distance per stretch of this length over well-conditioned scans, the median of the last
  /// `wheel_scale_stretches` once there are `wheel_scale_min_stretches`, at most
  /// `wheel_scale_max` from 1. The along prior needs it: the wheels' scale is off by up to ~1 %.
  /// 0 = the wheels as recorded [m]
  double wheel_scale_stretch_m = 50.0;
  int wheel_scale_stretches = 21;
  int wheel_scale_min_stretches = 5;
  double wheel_scale_max = 0.05;
  /// With IMU roll / pitch in odometry.csv: after each scan roll and pitch move this share of the
  /// way to the IMU's (LeGO-LOAM blends 0.002 per scan; 0 = off). Without it a pitch error
  /// taken on a ramp stays for good and the height wanders.
  double imu_tilt_weight = 0.2;
  /// The IMU's pitch bias measured at loop closures (slam/TiltBias): each closure's height
  /// correction over a path of at least tilt_bias_min_path_m, the median of the last
  /// tilt_bias_closures once there are tilt_bias_min_closures, at most tilt_bias_max_deg; it is
  /// taken off the IMU's pitch before the levelling. 0 = the IMU as recorded [m], [deg]
  double tilt_bias_min_path_m = 150.0;
  int tilt_bias_closures = 15;
  int tilt_bias_min_closures = 2;
  double tilt_bias_max_deg = 0.5;
  double failed_turn_decay = 0.9;  ///< a failed scan keeps the speed, the turn rate times this
  /// Without wheel odometry the constant-velocity prediction keeps only what a car does: forward
  /// speed and yaw rate. Its sideways and vertical speeds and roll / pitch rates are set to zero,
  /// so an error in one registration is not extrapolated into the next prediction (on a
  /// feature-poor street a full 6-DoF velocity let a height error grow from scan to scan).
  bool vehicle_motion = true;
  /// With vehicle_motion: how fast the predicted turn rate may change [deg/s^2]. A car's turn
  /// builds up over a second or so; bounded, one registration that turned a few degrees on a
  /// feature-poor street does not set the turn of the predictions after it. Two registrations in
  /// a row that agree on the new rate do (SUMO turns a car by up to 90 deg/s at once). 0 = off.
  double max_yaw_accel_deg_s2 = 60.0;
};

/// Scan-to-map registration against the local map of recent keyframes, and keyframe selection.
struct MappingConfig {
  void validate() const;  ///< values that cannot work: std::invalid_argument (Config.cpp)
  int iterations = 10;    ///< scan-to-map Gauss-Newton iterations
  /// ... without wheel odometry: the constant-velocity start is further off, and a heading left
  /// short of convergence becomes the next prediction's turn rate (a slow drift on a straight).
  int iterations_without_odometry = 20;
  int reassociate_every = 2;  ///< new neighbours / line and plane fits every n-th iteration
  double max_nn_m = 1.0;      ///< scan-to-map correspondence radius [m]
  /// > 0: a coarse stage with this radius first when scans are more than 0.15 s apart (stride-2
  /// turns); at 10 Hz it only risks a wrong minimum after a heading jump [m]
  double coarse_nn_m = 3.0;
  double edge_voxel_m = 0.2;         ///< voxel for edge features (source and local map) [m]
  double surf_voxel_m = 0.4;         ///< voxel for planar features (source and local map) [m]
  int max_source_edges = 3000;       ///< edge features per scan used for mapping (strided)
  int max_source_planes = 6000;      ///< planar features per scan used for mapping (strided)
  double local_map_update_m = 2.0;   ///< rebuild the local map after this much motion [m]
  int local_map_keyframes = 40;      ///< recent keyframes in the local map
  double local_map_radius_m = 60.0;  ///< and only those within this radius [m]
  double keyframe_distance_m = 1.0;  ///< new keyframe after this much motion [m]
  double keyframe_angle_deg = 10.0;  ///< ... or this much rotation [deg]
  double failed_keyframe_distance_m = 5.0;  ///< failed scans become keyframes only this far
                                            ///< from the last one (keeps the map clean) [m]
  /// Robust (Huber) kernel width for residuals, scan-to-scan and scan-to-map [m]. Not in
  /// LeGO-LOAM (it uses 1-0.9|d|): with 2 cm the registration ignores the noisy tail.
  double huber_m = 0.02;
  double plane_max_dev_m = 0.2;  ///< plane fit: all 5 neighbours within this [m] (LOAM 0.2)
  /// Weight of the point-to-line residuals against the point-to-plane ones in scan-to-map. The
  /// edges of round things (poles, trunks) are silhouettes that move round them with the
  /// viewpoint, so the map's lines lag behind the new scan's and pull it back along the street.
  /// Where the planes leave a direction free (an open street: along it) the edges alone still
  /// hold it at a tenth of the planes' weight.
  double edge_weight = 0.1;
  /// ... without odometry: there an open street's few posts are all that holds the motion along
  /// it from scan to scan, and at a tenth a 1 % wider robust kernel lost it (route1k open street
  /// 2.5 % drift), while the LiDAR-only shortfall along the street has another cause.
  double edge_weight_without_odometry = 1.0;
  int min_edge_features = 10;        ///< fewer edge matches: unreliable
  int min_plane_features = 50;       ///< fewer plane matches: unreliable
  double degeneracy_min_eig = 0.02;  ///< min normalised eigenvalue of the translation block
  bool degeneracy_remap = false;     ///< freeze degenerate directions in scan-to-map (LOAM)
};

/// Hypothesis search after a failed scan-to-map (not in LeGO-LOAM). SUMO switches a vehicle onto
/// a junction's internal lane with heading jumps of up to ~100 deg within one scan; local
/// registration cannot converge from there, so yaw hypotheses around the prediction are tried.
struct RelocaliseConfig {
  void validate() const;     ///< values that cannot work: std::invalid_argument (Config.cpp)
  bool enabled = true;       ///< yaw search when scan-to-map fails (without wheel odometry)
  double inlier_drop = 0.5;  ///< ... or when the inliers fall below this share of the recent level
  double ref_decay = 0.8;    ///< the recent level decays by this per scan
  double yaw_step_deg = 15.0;  ///< spacing of the yaw hypotheses over 360 deg [deg]
  int iterations = 6;          ///< Gauss-Newton iterations per hypothesis
  int max_points = 1500;       ///< source features per hypothesis (strided)
};

/// Loop closure (candidates, ICP verification, consistency checks) and the pose graph.
struct LoopConfig {
  void validate() const;  ///< values that cannot work: std::invalid_argument (Config.cpp)
  bool enabled = true;    ///< enable loop closure
  double radius_m = 7.0;  ///< search radius around the new keyframe's estimate [m]
  /// Old keyframes more than this above or below the new keyframe's estimate are not candidates:
  /// they are on another level (a bridge deck over the street, the street under it), whose scans
  /// see the deck from both sides, and ICP put two such keyframes 6.4 m apart at 5.6 m, which
  /// moved both streets' heights by 0.3 m the other way (docs/NOTES.md, "A closure between a
  /// bridge and the street under it"). Height drifts centimetres between closures with the IMU's
  /// pitch in the graph; a deck clears the street by 4 m or more [m]
  double max_height_gap_m = 2.0;
  double min_time_gap_s = 30.0;   ///< candidate must be older than this [s]
  int submap_keyframes = 10;      ///< keyframes each side of the candidate in its submap
  double voxel_m = 0.4;           ///< voxel for ICP clouds [m]
  int icp_iterations = 30;        ///< point-to-plane ICP iterations
  double icp_max_corr_m = 2.0;    ///< ICP correspondence distance (shrinks to a third) [m]
  double fitness_m2 = 0.09;       ///< accept if mean squared inlier distance below [m^2]
  double min_inlier_ratio = 0.5;  ///< ... and at least this share of points matched
  double cooldown_s = 5.0;        ///< min time between two accepted closures [s]
  /// Uniqueness check: an accepted ICP match is run again from its result shifted by these
  /// offsets along and across the new keyframe's heading (both signs). When one ends on another
  /// pose, more than ambiguity_separation_m away, that passes the same test and fits better, the
  /// first match stopped in a local minimum (one facade along a row of look-alikes); when it
  /// fits as well (inlier ratio at least ambiguity_rival_share of the match's, fitness at most
  /// the match's over it), ICP cannot tell where along the street it is (a bridge between
  /// uniform parapets stays wherever ICP starts, and a drifted estimate becomes the closure).
  /// Either way the candidate is refused. Empty offsets = off; rival share >= 1 = only better
  /// fits count [m], [1]
  std::vector<double> ambiguity_along_m = {3, 6, 9, 12};
  std::vector<double> ambiguity_across_m = {3, 6};
  double ambiguity_separation_m = 1.5;
  double ambiguity_inlier_margin = 0.0;
  double ambiguity_rival_share = 0.98;
  /// ... and refused when the match's horizontal conditioning (weakest over strongest direction
  /// of what the matched planes tell, horizontalConditioning) is below this: between two long
  /// plain walls (a bridge deck's parapets) ICP stays near where it started along the street,
  /// a metre or more off, without a rival standing out; on a feature-poor street at speed it
  /// slipped 3.9 m along the street at 0.095 (docs/NOTES.md, "A closure that slipped along an
  /// open street"). The fleet merge's value too. 0 = off
  double min_horizontal_conditioning = 0.1;
  /// ... and refused when its submap is not one rigid map: the new keyframe matched against the
  /// candidate's keyframes before it alone, and against those after it alone (from the whole
  /// submap's match; a side counts when its match passes the fitness test), ends more than this
  /// from the whole submap's match (SubmapAgreement.hpp). The relative pose to the candidate is
  /// then a blend of keyframe poses that disagree (a U-turn dead-reckoned inside the submap).
  /// Three loop-edge sigmas (graph_loop_sigma_m): beyond that the edge claims an accuracy its
  /// submap does not have. A match that is a better-fitting rival taken (ambiguity_* below) needs
  /// one side matched alone: with none, the check is empty, and such jumps of metres along an
  /// open street were look-alikes (docs/NOTES.md, "Rivals taken with nothing to back them").
  /// Negative = off [m]
  double submap_agreement_m = 0.3;
  /// A closure may move the new keyframe at most max_correction_m plus correction_per_m times
  /// the distance driven since the last accepted closure; a larger jump is taken for a look-alike
  /// place. Off by default: refusing true closures leaves the drift in place. Negative = no
  /// bound [m], [m/m]
  double max_correction_m = -1.0;
  double correction_per_m = 0.002;
  /// ... and refused when it and the closure accepted before it, joined by the keyframe chains
  /// between their old and between their new keyframes, do not close: the cycle may miss by
  /// consistency_m plus consistency_per_m times those chains' path (slam/ClosureCycle.hpp). A
  /// match 12 m along a street 7 s after a closure to the same street broke it by 12.7 m; true
  /// closures miss by the drift of short chains, well under 1 m. Negative = off [m], [m/m]
  double consistency_m = 1.0;
  double consistency_per_m = 0.02;
  /// Uniqueness check of a candidate before its ICP (CorrelativeSearch.hpp): the structure above
  /// the road of the new keyframe is scored at every x / y offset within the search window and
  /// every yaw within +-correlative_yaw_deg of the estimate against the candidate's submap. ICP
  /// starts from the best pose; the candidate is refused when a pose at least
  /// correlative_separation_m away scores correlative_max_ratio of the best or more: the drifted
  /// estimate may point at a look-alike stretch of street, where ICP alone finds a good fit with
  /// a small correction. The window, and the radius in which old keyframes are candidates, is
  /// radius_m + window_per_m x the path since the last closure, at most window_max_m: an
  /// estimate that drifted beyond radius_m still finds its revisit [m], [m/m], [deg].
  /// Off by default: on a whole-city drive it refused every look-alike closure but bent the
  /// map more than they had (docs/NOTES.md, "Correlative loop search").
  bool correlative = false;
  double window_per_m = 0.005;
  double window_max_m = 20.0;
  double correlative_yaw_deg = 4.0;
  double correlative_separation_m = 2.0;
  double correlative_max_ratio = 0.9;
  double graph_odom_sigma_m = 0.05;     ///< pose-graph odometry edge sigma (translation) [m]
  double graph_odom_sigma_rad = 0.005;  ///< pose-graph odometry edge sigma (rotation) [rad]
  double graph_loop_sigma_m = 0.1;      ///< loop edge sigma (translation) [m]
  double graph_loop_sigma_rad = 0.01;   ///< loop edge sigma (rotation) [rad]
  /// > 0: every keyframe's pitch is tied to the IMU's less its bias b, an unknown of the graph
  /// with a prior of 0 +- graph_pitch_bias_sigma_deg (PitchFactors): a closure's height mismatch
  /// then estimates b instead of bending the chain; the front end levels with b after each
  /// closure (in place of odometry.tilt_bias_*) and the graph is optimised once more at the end.
  /// The default is the simulated IMU's white noise (drive.odometry.tilt_noise_deg) [deg]; 0 = off.
  double graph_imu_pitch_sigma_deg = 0.1;
  double graph_pitch_bias_sigma_deg = 0.2;  ///< [deg]
  /// LiDAR-only runs (no wheel odometry): when no old keyframe lies within radius_m of the
  /// estimate (the drift since the last closure may be larger), a keyframe whose place
  /// descriptor matches is a candidate too, within a gate
  /// of radius_m + place_gate_per_m x the path since the last closure (at most place_gate_max_m):
  /// ICP starts at that keyframe turned by the descriptor's yaw, and the correction it finds must
  /// stay inside the gate (the odometry cannot have drifted further).
  bool place_recognition = true;
  double place_gate_per_m = 0.02;          ///< [m/m]
  double place_gate_max_m = 60.0;          ///< [m]
  double place_max_yaw_change_deg = 12.0;  ///< ICP may turn the descriptor's yaw at most [deg]
  PlaceRecognitionConfig place;            ///< the descriptor and its database
};

/// The map the SLAM writes.
struct OutputConfig {
  void validate() const;     ///< values that cannot work: std::invalid_argument (Config.cpp)
  double map_voxel_m = 0.2;  ///< voxel of the keyframe clouds and of map.pcd [m]
  /// The map is merged and written in square tiles of this size (MapTiles.hpp), so the merge
  /// holds one tile's voxels, not the whole map's. Same map points for any size [m].
  double map_tile_m = 400.0;
  /// Keyframe clouds in an unnamed file in the output folder instead of memory: same results,
  /// resident memory does not grow by ~47 kB per keyframe.
  bool keyframe_clouds_on_disk = true;
};

/// Trajectory and map metrics and plots.
struct MetricsConfig {
  void validate() const;            ///< values that cannot work: std::invalid_argument (Config.cpp)
  double map_accuracy_max_m = 2.0;  ///< distances are clamped here (points off the world) [m]
  double assoc_max_dt_s = 0.02;     ///< timestamp association tolerance [s]
  std::vector<double> rpe_lengths_m = {100, 200, 300, 400, 500, 600, 700, 800};  ///< KITTI [m]
  double rpe_segment_m = 50.0;  ///< extra user segment length for RPE [m]
  int rpe_step_frames = 10;     ///< start a segment every n frames (KITTI: 10)
  int plot_size_px = 1000;      ///< plot width and height [px]
};

struct Config {
  InputConfig input;
  FeaturesConfig features;
  OdometryConfig odometry;
  MappingConfig mapping;
  RelocaliseConfig relocalise;
  LoopConfig loop;
  OutputConfig output;
  MetricsConfig metrics;
  /// Throws std::invalid_argument naming the first field ("mapping.iterations must be ...") whose
  /// value cannot work. The config loader checks each section when it is loaded.
  void validate() const;
};

/// The flat keys of earlier config files and where each lives now ("odometry.use_wheel_odometry");
/// loading a file that still uses one is an error naming the new key.
const std::vector<std::pair<const char*, const char*>>& movedConfigKeys();

template <class V>
void visitFields(V& v, InputConfig& c) {
  v.field("scan_stride", c.scan_stride, "use every n-th scan (1 = all, 10 Hz)");
  v.field("dense_turn_rate_deg_s", c.dense_turn_rate_deg_s,
          "every scan above this turn rate, 0 = off [deg/s]");
  v.field("dense_after_failure_s", c.dense_after_failure_s,
          "every scan this long after a failure [s]");
  v.field("start_s", c.start_s, "evaluate scans from this drive time on [s]");
  v.field("end_s", c.end_s, "evaluate scans up to this drive time, 0 = to the end [s]");
}

template <class V>
void visitFields(V& v, FeaturesConfig& c) {
  v.field("deskew", c.deskew,
          "move each point to the sweep start with the predicted motion (scans with point times)");
  v.field("deskew_increments", c.deskew_increments,
          "without wheel odometry: the sweep's motion is the mean of this many registered steps");
  v.field("redeskew_without_odometry", c.redeskew_without_odometry,
          "without wheel odometry: deskew again with the step to the sweep's first registration");
  v.field("use_ring_field", c.use_ring_field, "use ScanPoint.ring when >= 0");
  v.field("ring_zero_is_bottom", c.ring_zero_is_bottom, "ring 0 is the lowest beam");
  v.field("min_range_m", c.min_range_m, "points closer are dropped [m]");
  v.field("min_valid_points", c.min_valid_points, "min valid points per scan");
  v.field("ground_max_elevation_deg", c.ground_max_elevation_deg,
          "beams below can be ground [deg]");
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
}

template <class V>
void visitFields(V& v, OdometryConfig& c) {
  v.field("use_wheel_odometry", c.use_wheel_odometry,
          "predict the motion between scans from the drive's wheel odometry + gyro (odometry.csv) "
          "if present");
  v.field("gyro_standstill_mps", c.gyro_standstill_mps,
          "gyro bias from the drive's stops: speed below this is standstill, 0 = off [m/s]");
  v.field("gyro_min_standstill_s", c.gyro_min_standstill_s,
          "standstill needed before the bias is used [s]");
  v.field("gyro_standstill_margin_s", c.gyro_standstill_margin_s,
          "standstill counts only this long after stopping and before starting [s]");
  v.field("two_step", c.two_step, "LeGO two-step scan-to-scan");
  v.field("iterations", c.iterations, "scan-to-scan iterations per step");
  v.field("max_nn_m", c.max_nn_m, "scan-to-scan correspondence radius [m]");
  v.field("max_step_change_m", c.max_step_change_m, "max change of the prediction per scan [m]");
  v.field("max_step_change_deg", c.max_step_change_deg,
          "max change of the prediction per scan [deg]");
  v.field("max_lateral_accel_mps2", c.max_lateral_accel_mps2,
          "turn rate bound: this over the speed, 0 = off [m/s^2]");
  v.field("rotation_slack_deg", c.rotation_slack_deg,
          "rotation allowed on top of the bound per scan [deg]");
  v.field("wheel_translation_slack_m", c.wheel_translation_slack_m,
          "with wheel odometry: registration may move its prediction this far per 0.1 s [m]");
  v.field("wheel_rotation_slack_deg", c.wheel_rotation_slack_deg,
          "with wheel odometry: ... and turn it this much in yaw per 0.1 s [deg]");
  v.field("slack_since_fix_max_s", c.slack_since_fix_max_s,
          "both slacks count the time since the last registered scan, at most this beyond the "
          "step; 0 = the step alone [s]");
  v.field("prior_sigma_m", c.prior_sigma_m,
          "scan-to-map prior towards the odometry, x/y sigma per 0.1 s (0 = off) [m]");
  v.field("prior_along_sigma_m", c.prior_along_sigma_m,
          "scan-to-map prior towards the odometry, along the heading only, sigma per 0.1 s "
          "(0 = off) [m]");
  v.field("prior_along_fade_info", c.prior_along_fade_info,
          "the along prior fades out as the scan's own information along the heading per "
          "residual rises to this (0 = always on)");
  v.field("velocity_prior_along_sigma_m", c.velocity_prior_along_sigma_m,
          "without wheel odometry: prior towards the constant-velocity prediction along the "
          "heading, sigma per 0.1 s; 0 = off [m]");
  v.field("velocity_prior_yaw_sigma_deg", c.velocity_prior_yaw_sigma_deg,
          "without wheel odometry: prior towards the constant-velocity prediction's yaw, sigma "
          "per 0.1 s; 0 = off [deg]");
  v.field("velocity_prior_yaw_fade_info", c.velocity_prior_yaw_fade_info,
          "... fading out as the scan's own yaw information (per residual) rises to this; 0 = "
          "always on");
  v.field("velocity_prior_fade_info", c.velocity_prior_fade_info,
          "... fading out as the scan's own information along the heading (per residual) rises "
          "to this; 0 = always on");
  v.field("prior_sigma_deg", c.prior_sigma_deg,
          "scan-to-map prior towards the odometry, yaw sigma per 0.1 s (0 = off) [deg]");
  v.field("prior_ref_noise_deg_s", c.prior_ref_noise_deg_s,
          "gyro white noise the yaw sigma is tuned for; a drive's odometry.yaml scales it, 0 = off "
          "[deg/s]");
  v.field("prior_ref_bias_deg_s", c.prior_ref_bias_deg_s, "... and gyro bias [deg/s]");
  v.field("prior_min_sigma_deg", c.prior_min_sigma_deg,
          "... but at least this (a noise-free gyro) [deg]");
  v.field("prior_registration_sigma_m", c.prior_registration_sigma_m,
          "LiDAR residual sigma for the odometry prior [m]");
  v.field("wheel_scale_stretch_m", c.wheel_scale_stretch_m,
          "wheel scale measured by the LiDAR over stretches of this length (0 = off) [m]");
  v.field("wheel_scale_stretches", c.wheel_scale_stretches,
          "... median over this many recent stretches");
  v.field("wheel_scale_min_stretches", c.wheel_scale_min_stretches,
          "... used once this many are measured");
  v.field("wheel_scale_max", c.wheel_scale_max, "... at most this far from 1 (0.05 = 5 %)");
  v.field("imu_tilt_weight", c.imu_tilt_weight,
          "share of the way roll/pitch move to the IMU's after each scan (odometry.csv with "
          "roll/pitch), 0 = off");
  v.field("tilt_bias_min_path_m", c.tilt_bias_min_path_m,
          "IMU pitch bias measured by loop closures after at least this path (0 = off) [m]");
  v.field("tilt_bias_closures", c.tilt_bias_closures, "... median over this many recent closures");
  v.field("tilt_bias_min_closures", c.tilt_bias_min_closures,
          "... used once this many are measured");
  v.field("tilt_bias_max_deg", c.tilt_bias_max_deg, "... at most this [deg]");
  v.field("failed_turn_decay", c.failed_turn_decay, "turn rate kept per failed scan (share)");
  v.field("vehicle_motion", c.vehicle_motion,
          "without wheel odometry, predict with forward speed and yaw rate only (false = full "
          "6-DoF velocity)");
  v.field(
      "max_yaw_accel_deg_s2", c.max_yaw_accel_deg_s2,
      "with vehicle_motion: largest change of the predicted turn rate [deg/s^2], 0 = unbounded");
}

template <class V>
void visitFields(V& v, MappingConfig& c) {
  v.field("iterations", c.iterations, "scan-to-map iterations");
  v.field("iterations_without_odometry", c.iterations_without_odometry,
          "scan-to-map iterations when the drive has no wheel odometry");
  v.field("reassociate_every", c.reassociate_every, "new correspondences every n-th iteration");
  v.field("max_nn_m", c.max_nn_m, "scan-to-map correspondence radius [m]");
  v.field("coarse_nn_m", c.coarse_nn_m, "coarse scan-to-map radius, 0 = off [m]");
  v.field("edge_voxel_m", c.edge_voxel_m, "edge voxel [m]");
  v.field("surf_voxel_m", c.surf_voxel_m, "planar voxel [m]");
  v.field("max_source_edges", c.max_source_edges, "edge features per scan for mapping");
  v.field("max_source_planes", c.max_source_planes, "planar features per scan for mapping");
  v.field("local_map_update_m", c.local_map_update_m, "local map rebuild distance [m]");
  v.field("local_map_keyframes", c.local_map_keyframes, "keyframes in the local map");
  v.field("local_map_radius_m", c.local_map_radius_m, "local map radius [m]");
  v.field("keyframe_distance_m", c.keyframe_distance_m, "keyframe spacing [m]");
  v.field("keyframe_angle_deg", c.keyframe_angle_deg, "keyframe rotation [deg]");
  v.field("failed_keyframe_distance_m", c.failed_keyframe_distance_m,
          "keyframe distance of failed scans [m]");
  v.field("huber_m", c.huber_m, "robust kernel width [m]");
  v.field("plane_max_dev_m", c.plane_max_dev_m, "plane fit max neighbour deviation [m]");
  v.field("edge_weight", c.edge_weight,
          "weight of the point-to-line (edge) residuals against the point-to-plane ones in "
          "scan-to-map (0, 1]");
  v.field("edge_weight_without_odometry", c.edge_weight_without_odometry,
          "edge_weight for runs without odometry (0, 1]");
  v.field("min_edge_features", c.min_edge_features, "min edge matches");
  v.field("min_plane_features", c.min_plane_features, "min plane matches");
  v.field("degeneracy_min_eig", c.degeneracy_min_eig, "min normalised translation eigenvalue");
  v.field("degeneracy_remap", c.degeneracy_remap, "freeze degenerate directions");
}

template <class V>
void visitFields(V& v, RelocaliseConfig& c) {
  v.field("enabled", c.enabled, "yaw search when scan-to-map fails");
  v.field("inlier_drop", c.inlier_drop, "inlier drop share triggering the search");
  v.field("ref_decay", c.ref_decay, "decay of the recent inlier level per scan");
  v.field("yaw_step_deg", c.yaw_step_deg, "yaw hypothesis spacing [deg]");
  v.field("iterations", c.iterations, "iterations per yaw hypothesis");
  v.field("max_points", c.max_points, "source features per hypothesis");
}

template <class V>
void visitFields(V& v, LoopConfig& c) {
  v.field("enabled", c.enabled, "enable loop closure");
  v.field("radius_m", c.radius_m, "loop search radius [m]");
  v.field("max_height_gap_m", c.max_height_gap_m,
          "old keyframes farther above or below the estimate are not candidates [m]");
  v.field("min_time_gap_s", c.min_time_gap_s, "loop min time gap [s]");
  v.field("submap_keyframes", c.submap_keyframes, "submap keyframes each side");
  v.field("voxel_m", c.voxel_m, "ICP voxel [m]");
  v.field("icp_iterations", c.icp_iterations, "ICP iterations");
  v.field("icp_max_corr_m", c.icp_max_corr_m, "ICP correspondence distance [m]");
  v.field("fitness_m2", c.fitness_m2, "ICP fitness threshold [m^2]");
  v.field("min_inlier_ratio", c.min_inlier_ratio, "ICP min inlier share");
  v.field("cooldown_s", c.cooldown_s, "min time between closures [s]");
  v.field("ambiguity_along_m", c.ambiguity_along_m,
          "closure refused when ICP from these offsets along the heading finds a better match, [] "
          "= off [m]");
  v.field("ambiguity_across_m", c.ambiguity_across_m, "... and across it [m]");
  v.field("ambiguity_separation_m", c.ambiguity_separation_m,
          "... at least this far from the first one [m]");
  v.field("ambiguity_inlier_margin", c.ambiguity_inlier_margin,
          "... matching this much larger a share of the points (and with a lower fitness)");
  v.field("ambiguity_rival_share", c.ambiguity_rival_share,
          "... or fitting as well: this share of the inliers and fitness (>= 1: only better)");
  v.field("min_horizontal_conditioning", c.min_horizontal_conditioning,
          "... or whose weakest over strongest horizontal information is below this (0 = off)");
  v.field("submap_agreement_m", c.submap_agreement_m,
          "... or when the submap's keyframes before and after the candidate, matched alone, put "
          "it farther than this apart (negative = off) [m]");
  v.field("correlative", c.correlative,
          "refuse a candidate that a pose elsewhere in the window fits nearly as well");
  v.field("window_per_m", c.window_per_m,
          "search window: radius_m + this x path since the last closure [m/m]");
  v.field("window_max_m", c.window_max_m, "... at most this [m]");
  v.field("correlative_yaw_deg", c.correlative_yaw_deg,
          "yaws searched around the estimate's [deg]");
  v.field("correlative_separation_m", c.correlative_separation_m,
          "a rival pose is at least this far from the best [m]");
  v.field("correlative_max_ratio", c.correlative_max_ratio,
          "refused when a rival scores this share of the best");
  v.field("max_correction_m", c.max_correction_m,
          "max jump of a loop closure right after another one (negative = no bound) [m]");
  v.field("correction_per_m", c.correction_per_m,
          "... plus this per metre driven since the last closure [m/m]");
  v.field("consistency_m", c.consistency_m,
          "max miss of the cycle with the closure before (negative = off) [m]");
  v.field("consistency_per_m", c.consistency_per_m,
          "... plus this per metre of the keyframe chains between the two closures [m/m]");
  v.field("graph_odom_sigma_m", c.graph_odom_sigma_m, "odometry edge sigma [m]");
  v.field("graph_odom_sigma_rad", c.graph_odom_sigma_rad, "odometry edge sigma [rad]");
  v.field("graph_loop_sigma_m", c.graph_loop_sigma_m, "loop edge sigma [m]");
  v.field("graph_loop_sigma_rad", c.graph_loop_sigma_rad, "loop edge sigma [rad]");
  v.field("graph_imu_pitch_sigma_deg", c.graph_imu_pitch_sigma_deg,
          "keyframe pitch tied to the IMU's less an estimated bias, sigma (0 = off) [deg]");
  v.field("graph_pitch_bias_sigma_deg", c.graph_pitch_bias_sigma_deg,
          "prior sigma of that IMU pitch bias [deg]");
  v.field("place_recognition", c.place_recognition,
          "LiDAR-only: candidates by place descriptor when none is near the estimate");
  v.field("place_gate_per_m", c.place_gate_per_m,
          "descriptor candidates within radius_m + this x path since the last closure [m/m]");
  v.field("place_gate_max_m", c.place_gate_max_m, "... at most this far [m]");
  v.field("place_max_yaw_change_deg", c.place_max_yaw_change_deg,
          "ICP may turn the descriptor's yaw at most [deg]");
  v.section("place", c.place);
}

template <class V>
void visitFields(V& v, OutputConfig& c) {
  v.field("map_voxel_m", c.map_voxel_m, "keyframe cloud and map.pcd voxel [m]");
  v.field("map_tile_m", c.map_tile_m, "map merged in tiles of this size [m]");
  v.field("keyframe_clouds_on_disk", c.keyframe_clouds_on_disk,
          "keyframe clouds in a temporary file, not memory");
}

template <class V>
void visitFields(V& v, MetricsConfig& c) {
  v.field("map_accuracy_max_m", c.map_accuracy_max_m, "map distance clamp [m]");
  v.field("assoc_max_dt_s", c.assoc_max_dt_s, "timestamp association tolerance [s]");
  v.field("rpe_lengths_m", c.rpe_lengths_m, "KITTI RPE segment lengths [m]");
  v.field("rpe_segment_m", c.rpe_segment_m, "user RPE segment length [m]");
  v.field("rpe_step_frames", c.rpe_step_frames, "RPE start stride [frames]");
  v.field("plot_size_px", c.plot_size_px, "plot size [px]");
}

template <class V>
void visitFields(V& v, Config& c) {
  v.section("input", c.input);
  v.section("features", c.features);
  v.section("odometry", c.odometry);
  v.section("mapping", c.mapping);
  v.section("relocalise", c.relocalise);
  v.section("loop", c.loop);
  v.section("output", c.output);
  v.section("metrics", c.metrics);
  for (const auto& [old_key, new_key] : movedConfigKeys()) v.moved(old_key, new_key);
}

}  // namespace slamroute::evaluate
