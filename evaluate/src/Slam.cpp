// LeGO-LOAM-style pipeline: the top-level addScan() reads as the paper's §3.3 steps.
#include "slamroute/evaluate/Slam.hpp"

#include <ctime>
#include <cmath>
#include <numbers>
#include <optional>
#include <stdexcept>

#include "slamroute/core/Log.hpp"
#include "slamroute/evaluate/CloudStore.hpp"
#include "slamroute/evaluate/MapTiles.hpp"
#include "slamroute/evaluate/MotionChecks.hpp"
#include "slamroute/evaluate/PoseGraph.hpp"
#include "slamroute/evaluate/RangeImage.hpp"
#include "slamroute/evaluate/Registration.hpp"

namespace slamroute::evaluate {
namespace {

/// Stage timing uses the thread's CPU time, so figures are per core and not distorted by other
/// processes competing for the machine.
struct Clock {
  static double now() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
  }
};
double since(double t0) { return Clock::now() - t0; }

/// Keeps at most `max_n` points, evenly strided (the input is voxel-sorted, so this thins space
/// uniformly).
Cloud capped(Cloud c, int max_n) {
  if (max_n <= 0 || c.size() <= static_cast<std::size_t>(max_n)) return c;
  Cloud out;
  out.reserve(static_cast<std::size_t>(max_n));
  const double step = static_cast<double>(c.size()) / max_n;
  for (int i = 0; i < max_n; ++i) out.push_back(c[static_cast<std::size_t>(i * step)]);
  return out;
}

struct Keyframe {
  double t = 0;
  int frame = 0;
  Pose3 T_world = Pose3::Identity();
  Cloud edges, planes;  ///< body frame, voxel-filtered (scan-to-map source / local map)
  int cloud = -1;       ///< in Impl::clouds: body frame, segmented points at cfg.map_voxel_m (map + ICP)
};

struct FrameRecord {
  double t = 0;
  int keyframe = 0;
  Pose3 T_kf_frame = Pose3::Identity();
  FrameStatus status = FrameStatus::Ok;
  double min_eig = 0;
};

}  // namespace

const char* toString(FrameStatus s) {
  switch (s) {
    case FrameStatus::Ok: return "ok";
    case FrameStatus::Empty: return "empty_scan";
    case FrameStatus::Invalid: return "too_few_valid_points";
    case FrameStatus::Missing: return "missing_scan";
    case FrameStatus::FewFeatures: return "few_features";
    case FrameStatus::Degenerate: return "degenerate_geometry";
  }
  return "unknown";
}

struct LidarSlam::Impl {
  Config cfg;
  LidarSpec spec;
  Pose3 T_world_first;
  std::vector<FrameRecord> frames;
  std::vector<Keyframe> kfs;
  std::unique_ptr<CloudStore> clouds = std::make_unique<CloudStore>();  ///< the keyframes' clouds
  MapSink* map_sink = nullptr;  ///< where finish() puts the map (none: SlamResult::map)
  std::vector<PoseGraphEdge> odom_edges, loop_edges;
  std::vector<LoopClosure> loops;
  int loop_candidates = 0;
  int loops_rejected = 0;           ///< ICP matches refused for too large a correction
  int loops_ambiguous = 0;          ///< ICP matches refused: ICP from nearby starts fits better elsewhere
  double driven_since_loop = 0.0;   ///< keyframe path since the last accepted closure [m]
  double last_loop_t = -1e18, last_attempt_t = -1e18;
  bool have_prev = false;
  FeatureMap prev_scan;  ///< previous good scan's less-sharp / less-flat, its body frame
  FeatureMap local_map;  ///< world frame
  Vec3 local_map_at = Vec3::Constant(1e18);  ///< where the local map was last rebuilt
  Pose3 T_world_last = Pose3::Identity();  ///< last frame (good or predicted)
  Pose3 T_world_good = Pose3::Identity();  ///< last well-registered frame
  int good_frame = -1;
  Pose3 velocity = Pose3::Identity();      ///< motion over velocity_dt, body frame
  double velocity_dt = 0.1;                ///< [s]
  bool have_velocity = false;              ///< velocity measured (not the initial guess)
  bool last_failed = false;                ///< the previous scan failed
  double dense_until_t = -1e18;            ///< take every scan until then (after a failure) [s]
  bool check_motion = true;                ///< apply the dynamics check (off after a relocalisation,
                                           ///< whose jump makes the next prediction unreliable)
  double inlier_ref = 0;                   ///< recent scan-to-map inlier level (0: none)
  WheelOdometry odometry;                  ///< wheel speed + gyro (empty: constant velocity)
  StageTimes times;

  /// Prediction of the pose at time t (frames may be unevenly spaced): the wheel odometry's
  /// planar motion (height from the velocity) when there is odometry, else constant velocity.
  /// `plausible`, and with wheel odometry also within its slack of the odometry's prediction.
  bool plausibleStep(const Pose3& pred, const Pose3& result, double dt, double speed) const {
    return plausible(pred, result, cfg, dt, speed) &&
           (odometry.empty() || plausibleWithOdometry(pred, result, cfg, dt));
  }

  /// Prior of the scan-to-map towards the odometry's prediction (x, y, yaw), its sigmas grown
  /// with the frame interval like the slack.
  void setOdometryPrior(AlignOptions& o, const Pose3& pred, double scale) const {
    o.prior = pred;
    const auto w = [&](double sigma) {
      return sigma > 0 ? std::pow(cfg.registration_sigma_m / (sigma * scale), 2) : 0.0;
    };
    o.prior_weight.setZero();
    o.prior_weight(2) = w(cfg.odometry_prior_sigma_deg * std::numbers::pi / 180.0);
    o.prior_weight(3) = o.prior_weight(4) = w(cfg.odometry_prior_sigma_m);
  }

  Pose3 predict(double t) const {
    if (frames.empty()) return T_world_last;
    const Pose3 v = scaledMotion(velocity, (t - frames.back().t) / velocity_dt);
    if (odometry.empty()) return T_world_last * v;
    Pose3 m = odometry.motion(frames.back().t, t);
    if (have_velocity) m.translation().z() = v.translation().z();
    return T_world_last * m;
  }

  void record(double t, const Pose3& T_world, FrameStatus s, double min_eig) {
    FrameRecord r;
    r.t = t;
    r.status = s;
    r.min_eig = min_eig;
    r.keyframe = static_cast<int>(kfs.size()) - 1;
    if (r.keyframe >= 0) r.T_kf_frame = kfs.back().T_world.inverse() * T_world;
    else r.T_kf_frame = T_world;  // before the first keyframe: absolute (kf -1 = world)
    frames.push_back(r);
    T_world_last = T_world;
  }

  FrameStatus addUnusable(double t, FrameStatus s) {
    const Pose3 T = frames.empty() ? T_world_first : predict(t);
    record(t, T, s, 0.0);
    return s;
  }

  void rebuildLocalMap(bool force) {
    const Vec3 here = kfs.back().T_world.translation();
    if (!force && (here - local_map_at).norm() < cfg.local_map_update_m) return;
    local_map_at = here;
    Cloud edges, planes;
    const int n = static_cast<int>(kfs.size());
    for (int k = n - 1; k >= 0 && k >= n - cfg.local_map_keyframes; --k) {
      const Keyframe& kf = kfs[static_cast<std::size_t>(k)];
      if ((kf.T_world.translation() - here).norm() > cfg.local_map_radius_m) continue;
      const Cloud e = transformed(kf.edges, kf.T_world), p = transformed(kf.planes, kf.T_world);
      edges.insert(edges.end(), e.begin(), e.end());
      planes.insert(planes.end(), p.begin(), p.end());
    }
    local_map.build(voxelFilter(edges, cfg.map_edge_voxel_m), voxelFilter(planes, cfg.map_surf_voxel_m));
  }

  /// Paper §3.3 / LeGO-LOAM: ICP of the new keyframe against an old keyframe's submap, then
  /// pose-graph optimisation.
  bool tryLoopClosure() {
    const Keyframe& cur = kfs.back();
    if (cur.t - last_loop_t < cfg.loop_cooldown_s || cur.t - last_attempt_t < 1.0) return false;
    int best = -1;
    double best_d = cfg.loop_radius_m;
    for (std::size_t k = 0; k + 1 < kfs.size(); ++k) {
      if (cur.t - kfs[k].t < cfg.loop_min_time_gap_s) break;  // keyframes are in time order
      const double d = (kfs[k].T_world.translation() - cur.T_world.translation()).norm();
      if (d < best_d) {
        best_d = d;
        best = static_cast<int>(k);
      }
    }
    if (best < 0) return false;
    last_attempt_t = cur.t;
    ++loop_candidates;
    Cloud target;
    const int n = static_cast<int>(kfs.size());
    for (int k = std::max(0, best - cfg.loop_submap_keyframes);
         k <= std::min(n - 2, best + cfg.loop_submap_keyframes); ++k) {
      const Keyframe& kf = kfs[static_cast<std::size_t>(k)];
      if (cur.t - kf.t < cfg.loop_min_time_gap_s) continue;
      const Cloud c = transformed(clouds->get(kf.cloud), kf.T_world);
      target.insert(target.end(), c.begin(), c.end());
    }
    const IcpTarget icp_target(voxelFilter(target, cfg.loop_voxel_m));
    const Cloud source = voxelFilter(clouds->get(cur.cloud), cfg.loop_voxel_m);
    const IcpResult icp = icp_target.align(source, cur.T_world, cfg.loop_icp_iterations, cfg.loop_icp_max_corr_m);
    logDebug("loop candidate kf " + std::to_string(best) + " -> " + std::to_string(n - 1) +
             ": fitness " + std::to_string(icp.fitness_m2) + " inliers " +
             std::to_string(icp.inlier_ratio));
    const IcpAcceptance accept{cfg.loop_fitness_m2, cfg.loop_min_inlier_ratio};
    if (!accept(icp)) return false;
    const IcpAmbiguity amb{cfg.loop_ambiguity_along_m, cfg.loop_ambiguity_across_m, cfg.loop_ambiguity_separation_m,
                           cfg.loop_ambiguity_inlier_margin, cfg.loop_icp_iterations, cfg.loop_icp_max_corr_m, accept};
    if (const auto other = betterIcpMatch(icp_target, source, icp, amb)) {
      ++loops_ambiguous;
      logDebug("loop candidate refused: a match " + std::to_string(*other) + " m away fits better");
      return false;
    }
    const double correction = (icp.T_target_source.translation() - cur.T_world.translation()).norm();
    if (!plausibleLoopCorrection(correction, driven_since_loop, cfg)) {
      ++loops_rejected;
      logDebug("loop candidate rejected: correction " + std::to_string(correction) + " m after " +
               std::to_string(driven_since_loop) + " m");
      return false;
    }
    PoseGraphEdge e;
    e.from = best;
    e.to = n - 1;
    e.T_from_to = kfs[static_cast<std::size_t>(best)].T_world.inverse() * icp.T_target_source;
    e.sigma_m = cfg.graph_loop_sigma_m;
    e.sigma_rad = cfg.graph_loop_sigma_rad;
    loop_edges.push_back(e);
    loops.push_back({best, n - 1, kfs[static_cast<std::size_t>(best)].t, cur.t, icp.fitness_m2, correction,
                     e.T_from_to});
    last_loop_t = cur.t;
    driven_since_loop = 0.0;
    const auto t0 = Clock::now();
    std::vector<Pose3> poses;
    for (const auto& kf : kfs) poses.push_back(kf.T_world);
    std::vector<PoseGraphEdge> edges = odom_edges;
    edges.insert(edges.end(), loop_edges.begin(), loop_edges.end());
    optimizePoseGraph(poses, edges, 0);
    for (std::size_t k = 0; k < kfs.size(); ++k) kfs[k].T_world = poses[k];
    times.pose_graph += since(t0);
    logInfo("loop closure: keyframe " + std::to_string(n - 1) + " (t=" + std::to_string(cur.t) +
            " s) matches keyframe " + std::to_string(best) + ", fitness " +
            std::to_string(icp.fitness_m2) + " m^2");
    return true;
  }

  void addKeyframe(double t, const Pose3& T_world, const Cloud& edges, const Cloud& planes,
                   const Cloud& segmented) {
    Keyframe kf;
    kf.t = t;
    kf.frame = static_cast<int>(frames.size());
    kf.T_world = T_world;
    kf.edges = edges;
    kf.planes = planes;
    kf.cloud = clouds->add(voxelFilter(segmented, cfg.map_voxel_m));
    if (!kfs.empty()) {
      driven_since_loop += (T_world.translation() - kfs.back().T_world.translation()).norm();
      PoseGraphEdge e;
      e.from = static_cast<int>(kfs.size()) - 1;
      e.to = e.from + 1;
      e.T_from_to = kfs.back().T_world.inverse() * T_world;
      e.sigma_m = cfg.graph_odom_sigma_m;
      e.sigma_rad = cfg.graph_odom_sigma_rad;
      odom_edges.push_back(e);
    }
    kfs.push_back(std::move(kf));
    // Only the recent keyframes feed the local map: free the features of older ones.
    if (kfs.size() > static_cast<std::size_t>(std::max(cfg.local_map_keyframes, 1))) {
      Keyframe& old = kfs[kfs.size() - 1 - static_cast<std::size_t>(std::max(cfg.local_map_keyframes, 1))];
      Cloud().swap(old.edges);
      Cloud().swap(old.planes);
    }
    bool closed = false;
    if (cfg.loop_closure) {
      const auto t0 = Clock::now();
      closed = tryLoopClosure();
      times.loop_closure += since(t0);
    }
    const auto t0 = Clock::now();
    rebuildLocalMap(closed || kfs.size() == 1);
    times.local_map += since(t0);
  }

  /// Hypothesis search after a failed scan-to-map: yaw over 360 deg around the prediction, or,
  /// before the speed is known (second scan), forward offsets. Every hypothesis gets a few coarse
  /// iterations; the one with the most inliers wins if it is not the prediction itself and has
  /// clearly more inliers than the prediction, and is then refined.
  bool relocalize(const Pose3& pred, const Cloud& src_edges, const Cloud& src_planes,
                  const AlignOptions& mo, int failed_inliers, Pose3& out, int& inliers) {
    const int cap = std::max(50, cfg.relocalize_max_points);
    const Cloud ce = capped(src_edges, cap / 4), cp = capped(src_planes, cap);
    AlignOptions co = mo;
    co.degenerate_eig = 0;
    co.iterations = cfg.relocalize_iterations;
    std::vector<Pose3> hyp;  // hyp[0] is the prediction
    if (have_velocity) {
      const double step = std::max(1.0, cfg.relocalize_yaw_step_deg);
      const int n = static_cast<int>(std::floor(360.0 / step + 1e-9));
      for (int k = 0; k < n; ++k) {
        Pose3 h = pred;
        h.linear() = pred.rotation() *
                     Eigen::AngleAxisd(k * step * std::numbers::pi / 180.0, Vec3::UnitZ()).toRotationMatrix();
        hyp.push_back(h);
      }
    } else {
      for (int k : {0, -1, 1, -2, 2, -3, 3, -4, 4}) hyp.push_back(pred * Eigen::Translation3d(k * 1.0, 0.0, 0.0));
    }
    int inl_ref = 0;
    int best_inl = -1;
    Pose3 best_T = pred;
    std::size_t best = 0;
    for (std::size_t k = 0; k < hyp.size(); ++k) {
      const AlignResult r = alignFeatures(local_map, ce, cp, hyp[k], co);
      if (k == 0) inl_ref = r.inliers;
      if (r.inliers > best_inl) {
        best_inl = r.inliers;
        best_T = r.T_target_source;
        best = k;
      }
    }
    // Another hypothesis must clearly beat the prediction; the prediction's own coarse result
    // (wider basin than the failed registration) must beat that registration's inliers.
    if (best != 0 && best_inl < 1.5 * inl_ref + 20) return false;
    const AlignResult m = alignFeatures(local_map, src_edges, src_planes, best_T, mo);
    if (m.edge_matches < cfg.min_edge_features || m.plane_matches < cfg.min_plane_features) return false;
    if (best == 0 && m.inliers < 1.5 * failed_inliers + 20) return false;
    out = m.T_target_source;
    inliers = m.inliers;
    logDebug("relocalised: inliers " + std::to_string(best_inl) + " vs " + std::to_string(inl_ref));
    return true;
  }

  FrameStatus addScan(const Scan& scan) {
    const auto t_all = Clock::now();
    auto t0 = Clock::now();
    // 1. range-image projection, ground segmentation, clustering
    RangeImage img = projectScan(scan, spec, cfg);
    times.projection += since(t0);
    if (img.valid_points == 0) {
      times.total += since(t_all);
      return addUnusable(scan.t, scan.points.empty() ? FrameStatus::Empty : FrameStatus::Invalid);
    }
    if (img.valid_points < cfg.min_valid_points) {
      times.total += since(t_all);
      return addUnusable(scan.t, FrameStatus::Invalid);
    }
    t0 = Clock::now();
    segmentGround(img, cfg);
    times.ground += since(t0);
    t0 = Clock::now();
    clusterRangeImage(img, cfg);
    times.clustering += since(t0);
    // 2. edge / planar features
    t0 = Clock::now();
    const FeatureSet f = extractFeatures(img, cfg);
    // Keyframes keep all voxel-filtered features (a dense local map); the scan-to-map source is
    // thinned to a fixed budget for speed.
    const Cloud kf_edges = voxelFilter(f.less_sharp, cfg.map_edge_voxel_m);
    const Cloud kf_planes = cfg.map_surf_voxel_m == cfg.less_flat_voxel_m
                                ? f.less_flat
                                : voxelFilter(f.less_flat, cfg.map_surf_voxel_m);
    const Cloud src_edges = capped(kf_edges, cfg.map_max_source_edges);
    const Cloud src_planes = capped(kf_planes, cfg.map_max_source_planes);
    times.features += since(t0);

    const int index = static_cast<int>(frames.size());
    if (!have_prev) {  // first usable scan: start (or restart) at the prediction
      const Pose3 T = frames.empty() ? T_world_first : predict(scan.t);
      have_prev = true;
      prev_scan.build(f.less_sharp, f.less_flat);
      T_world_good = T;
      good_frame = index;
      addKeyframe(scan.t, T, kf_edges, kf_planes, f.segmented);
      record(scan.t, kfs.back().T_world, FrameStatus::Ok, 1.0);
      times.total += since(t_all);
      return FrameStatus::Ok;
    }
    // 3. scan-to-scan odometry (LeGO-LOAM two-step: planar -> z/roll/pitch, edges -> x/y/yaw)
    t0 = Clock::now();
    const Pose3 pred = predict(scan.t);
    const double dt = scan.t - frames.back().t;
    const double scale = std::max(1.0, dt / 0.1);
    const double speed = have_velocity ? velocity.translation().norm() / velocity_dt : 0.0;
    const Pose3 T_prev_pred = T_world_good.inverse() * pred;
    Pose3 T_prev_curr = T_prev_pred;
    AlignOptions ao;
    ao.iterations = cfg.odom_iterations;
    ao.max_nn_m = cfg.odom_max_nn_m;
    ao.huber_m = cfg.huber_m;
    ao.plane_max_dev_m = cfg.plane_max_dev_m;
    if (cfg.two_step_odometry) {
      ao.dof_mask = kZ | kRoll | kPitch;
      AlignResult r1 = alignFeatures(prev_scan, {}, f.flat, T_prev_curr, ao);
      if (r1.plane_matches >= cfg.min_plane_features) T_prev_curr = r1.T_target_source;
      ao.dof_mask = kX | kY | kYaw;
      AlignResult r2 = alignFeatures(prev_scan, f.sharp, {}, T_prev_curr, ao);
      if (r2.edge_matches >= cfg.min_edge_features) T_prev_curr = r2.T_target_source;
    } else {
      AlignResult r = alignFeatures(prev_scan, f.sharp, f.flat, T_prev_curr, ao);
      if (r.edge_matches + r.plane_matches >= cfg.min_plane_features) T_prev_curr = r.T_target_source;
    }
    bool implausible = false;
    const bool check = have_velocity && check_motion;
    if (check && !plausibleStep(T_prev_pred, T_prev_curr, dt, speed)) {
      T_prev_curr = T_prev_pred;
      implausible = true;
    }
    times.odometry += since(t0);
    // 4. scan-to-map refinement against the local keyframe map
    t0 = Clock::now();
    Pose3 T_world = T_world_good * T_prev_curr;
    AlignOptions mo;
    mo.iterations = cfg.map_iterations;
    mo.reassociate_every = cfg.map_reassociate_every;
    mo.max_nn_m = cfg.map_max_nn_m;
    mo.huber_m = cfg.huber_m;
    mo.plane_max_dev_m = cfg.plane_max_dev_m;
    if (cfg.degeneracy_remap) mo.degenerate_eig = cfg.degeneracy_min_eig;
    if (!odometry.empty()) setOdometryPrior(mo, pred, scale);
    if (cfg.map_coarse_nn_m > 0 && have_velocity && scale > 1.5) {
      // Coarse stage with a wide correspondence radius: widens the basin of convergence when the
      // prediction is off by several degrees (turns at a scan stride of 2). Only for frame
      // intervals above 0.15 s: at 10 Hz it is not needed, and on /tmp/dq_s it let the
      // registration settle on a wrong minimum after the 95 deg heading jump (ATE 0.088 -> 125 m).
      const int cap = std::max(50, cfg.relocalize_max_points);
      AlignOptions co = mo;
      co.max_nn_m = cfg.map_coarse_nn_m;
      co.iterations = cfg.relocalize_iterations;
      co.degenerate_eig = 0;
      const AlignResult c = alignFeatures(local_map, capped(src_edges, cap / 4), capped(src_planes, cap), T_world, co);
      if (c.edge_matches >= cfg.min_edge_features && c.plane_matches >= cfg.min_plane_features &&
          plausibleStep(pred, c.T_target_source, dt, speed))
        T_world = c.T_target_source;
    }
    const AlignResult m = alignFeatures(local_map, src_edges, src_planes, T_world, mo);
    if (index % 50 == 0)
      logDebug("scan " + std::to_string(index) + ": sharp " + std::to_string(f.sharp.size()) +
               " flat " + std::to_string(f.flat.size()) + " src edges " + std::to_string(src_edges.size()) +
               " src planes " + std::to_string(src_planes.size()) + " map edges " +
               std::to_string(local_map.edges.size()) + " map planes " +
               std::to_string(local_map.planes.size()) + " iterations " + std::to_string(m.iterations) +
               " min eig " + std::to_string(m.min_eig_translation));
    FrameStatus status = implausible ? FrameStatus::Degenerate : FrameStatus::Ok;
    bool failed = false;
    if (m.edge_matches < cfg.min_edge_features || m.plane_matches < cfg.min_plane_features) {
      status = FrameStatus::FewFeatures;  // keep the odometry pose in x, y, yaw
      failed = true;
      // Scan-to-scan on a handful of edges is no better: wheel odometry + gyro are, when present.
      if (!odometry.empty()) T_world = pred;
      // Too few edges (an open street): the planes still fix height, roll and pitch.
      AlignOptions po = mo;
      po.dof_mask = kZ | kRoll | kPitch;
      const AlignResult g = alignFeatures(local_map, {}, src_planes, T_world, po);
      if (g.plane_matches >= cfg.min_plane_features && plausibleStep(pred, g.T_target_source, dt, speed))
        T_world = g.T_target_source;
    } else if (check && !plausibleStep(pred, m.T_target_source, dt, speed)) {
      status = FrameStatus::Degenerate;   // keep the odometry pose
      failed = true;
    } else {
      T_world = m.T_target_source;
      if (m.min_eig_translation < cfg.degeneracy_min_eig) status = FrameStatus::Degenerate;
    }
    // A sudden drop of the inliers (residual < 0.1 m) against the previous scan means the
    // registration settled in a wrong minimum (e.g. a heading jump): try the hypotheses too.
    const bool inlier_drop = inlier_ref > 0 && m.inliers < cfg.relocalize_inlier_drop * inlier_ref;
    int inliers = m.inliers;
    check_motion = true;
    if ((failed || inlier_drop) && !last_failed) dense_until_t = scan.t + cfg.dense_after_failure_s;
    // The search needs edges: in a featureless stretch (open field) it cannot succeed.
    const bool searchable = static_cast<int>(src_edges.size()) >= cfg.min_edge_features;
    // With wheel odometry + gyro the pose may not leave the odometry's slack anyway, and the
    // prediction is inside the registration's basin: the search only costs time (on the first
    // 200 s of the `run` qlearning drive it was 40 % of the SLAM time and changed nothing).
    const bool search = cfg.relocalize && searchable && odometry.empty();
    if ((failed || inlier_drop || !have_velocity) && search) {
      Pose3 T_reloc;
      if (relocalize(pred, src_edges, src_planes, mo, m.inliers, T_reloc, inliers)) {
        T_world = T_reloc;
        status = FrameStatus::Ok;
        failed = false;
        check_motion = false;
      }
    }
    if (failed || inlier_drop || !check_motion || implausible) {
      const auto yawDeg = [](const Pose3& T) {
        return std::to_string(std::atan2(T.rotation()(1, 0), T.rotation()(0, 0)) * 180.0 / std::numbers::pi);
      };
      logDebug("t=" + std::to_string(scan.t) + " s: " + toString(status) + (failed ? " (failed)" : "") +
               (check_motion ? "" : " relocalised") + (implausible ? " odometry implausible" : "") +
               ", inliers " + std::to_string(m.inliers) + " (recent " + std::to_string(static_cast<int>(inlier_ref)) +
               "), edge/plane matches " + std::to_string(m.edge_matches) + "/" + std::to_string(m.plane_matches) +
               ", yaw " + yawDeg(T_world) + " deg (predicted " + yawDeg(pred) + ")");
    }
    // The reference follows rising inlier counts at once and falling ones slowly, so a sudden drop
    // stands out while a gradual change of scenery does not trigger searches.
    if (!failed) inlier_ref = std::max(static_cast<double>(inliers), cfg.relocalize_ref_decay * inlier_ref);
    times.mapping += since(t0);
    // Absolute roll / pitch from the IMU's gravity vector, when the drive has them.
    if (cfg.imu_tilt_weight > 0)
      if (const auto a = odometry.attitude(scan.t))
        T_world = levelled(T_world, a->roll_rad, a->pitch_rad, cfg.imu_tilt_weight);
    // motion model for the next prediction
    // Motion model. A relocalised pose is a correction, not motion: keep the speed and go
    // straight ahead (the next scans are taken densely, so a fast turn is followed from there).
    // The turn rate is clamped to what a car can drive at that speed, so a wrong pose cannot make
    // the prediction spin on.
    // A failed scan measures no motion: keep the speed, let the turn rate fade (streets are
    // mostly straight where features are missing).
    if (failed && have_velocity) {
      velocity.linear() = scaledMotion(velocity, cfg.failed_turn_decay).linear();
    } else if (!check_motion && have_velocity) {
      velocity.linear().setIdentity();
    } else if (index - good_frame == 1) {
      velocity = T_world_good.inverse() * T_world;
      velocity_dt = std::max(1e-3, dt);
      have_velocity = true;
      const double angle = rotationAngle(velocity);
      const double max_angle = maxTurnRate(cfg, velocity.translation().norm() / velocity_dt) * velocity_dt;
      if (angle > max_angle) velocity.linear() = scaledMotion(velocity, max_angle / angle).linear();
    }
    last_failed = failed;
    prev_scan.build(f.less_sharp, f.less_flat);
    T_world_good = T_world;
    good_frame = index;
    // 5. keyframes (+ loop closure and pose graph inside)
    const Pose3 rel = kfs.back().T_world.inverse() * T_world;
    const bool kf_due = failed ? rel.translation().norm() > cfg.failed_keyframe_distance_m
                               : (rel.translation().norm() > cfg.keyframe_distance_m ||
                                  rotationAngle(rel) > cfg.keyframe_angle_deg * std::numbers::pi / 180.0);
    if (kf_due) {
      addKeyframe(scan.t, T_world, kf_edges, kf_planes, f.segmented);
      T_world = kfs.back().T_world;  // may have moved in the pose graph
      T_world_good = T_world;
    }
    record(scan.t, T_world, status, m.min_eig_translation);
    times.total += since(t_all);
    return status;
  }

  SlamResult finish() {
    SlamResult out;
    for (const auto& r : frames) {
      StampedPose sp;
      sp.t = r.t;
      sp.T_world_body = r.keyframe >= 0 ? kfs[static_cast<std::size_t>(r.keyframe)].T_world * r.T_kf_frame
                                        : r.T_kf_frame;
      out.trajectory.push_back(sp);
      out.status.push_back(r.status);
      out.min_eig.push_back(r.min_eig);
    }
    // The map: every keyframe's cloud at its optimised pose, voxel-filtered tile by tile into the
    // sink (each keyframe's cloud is freed after its last tile; the run is over).
    std::vector<MapKeyframe> map_kfs;
    map_kfs.reserve(kfs.size());
    for (const auto& kf : kfs) map_kfs.push_back({kf.cloud, kf.T_world});
    CollectedMap collected;
    MapSink& sink = map_sink ? *map_sink : collected;
    sink.estimate(out.trajectory);
    std::optional<Progress> progress;  // the tiles are counted inside
    out.map_points = buildMapByTiles(*clouds, map_kfs, cfg.map_voxel_m, cfg.map_tile_m, sink,
                                     [&](std::size_t done, std::size_t total) {
                                       if (!progress) progress.emplace("SLAM: map tiles", total);
                                       progress->update(done);
                                     });
    if (progress) progress->finish();
    out.map = std::move(collected.map);
    if (clouds->onDisk())
      logInfo("SLAM: the keyframes' clouds took " + std::to_string(clouds->bytesOnDisk() / 1000000) +
              " MB in a temporary file (" + std::to_string(kfs.size()) + " keyframes)");
    out.loops = loops;
    out.loop_candidates = loop_candidates;
    out.loops_rejected = loops_rejected;
    out.loops_ambiguous = loops_ambiguous;
    out.keyframes = static_cast<int>(kfs.size());
    out.times = times;
    return out;
  }
};

void LidarSlam::setMapSink(MapSink& sink) { impl_->map_sink = &sink; }

void LidarSlam::keepCloudsOnDisk(const std::filesystem::path& dir) {
  if (!impl_->kfs.empty()) throw std::logic_error("LidarSlam::keepCloudsOnDisk: call it before the first scan");
  impl_->clouds = std::make_unique<CloudStore>(dir);
}

LidarSlam::LidarSlam(const Config& cfg, const LidarSpec& spec, const Pose3& T_world_first)
    : impl_(std::make_unique<Impl>()) {
  impl_->cfg = cfg;
  impl_->spec = spec;
  impl_->T_world_first = T_world_first;
  impl_->T_world_last = T_world_first;
}
LidarSlam::~LidarSlam() = default;
void LidarSlam::setInitialMotion(const Pose3& T_first_second, double dt_s) {
  if (!(dt_s > 0)) throw std::invalid_argument("initial motion: time step must be positive");
  impl_->velocity = T_first_second;
  impl_->velocity_dt = dt_s;
  impl_->have_velocity = true;
}
FrameStatus LidarSlam::addScan(const Scan& scan) { return impl_->addScan(scan); }
FrameStatus LidarSlam::addMissing(double t) { return impl_->addUnusable(t, FrameStatus::Missing); }
Pose3 LidarSlam::currentPose() const { return impl_->T_world_last; }
void LidarSlam::setOdometry(WheelOdometry odometry) { impl_->odometry = std::move(odometry); }
double LidarSlam::turnRateDegPerS() const {
  if (!impl_->odometry.empty() && !impl_->frames.empty())
    return std::abs(impl_->odometry.yawRate(impl_->frames.back().t)) * 180.0 / std::numbers::pi;
  if (!impl_->have_velocity) return 0.0;
  return rotationAngle(impl_->velocity) / impl_->velocity_dt * 180.0 / std::numbers::pi;
}
bool LidarSlam::wantsEveryScan() const {
  const Impl& s = *impl_;
  if (s.frames.empty()) return false;
  if (s.frames.back().t < s.dense_until_t) return true;
  return s.cfg.dense_turn_rate_deg_s > 0 && turnRateDegPerS() > s.cfg.dense_turn_rate_deg_s;
}
SlamResult LidarSlam::finish() { return impl_->finish(); }

SlamResult runSlam(const ScanSource& source, const Config& cfg, const Pose3& T_world_first,
                   const std::function<void(std::size_t, std::size_t)>& progress,
                   const std::optional<Pose3>& T_first_second, const WheelOdometry* odometry,
                   const std::filesystem::path& cloud_dir, MapSink* map_sink) {
  LidarSlam slam(cfg, source.spec(), T_world_first);
  if (!cloud_dir.empty()) slam.keepCloudsOnDisk(cloud_dir);
  if (map_sink) slam.setMapSink(*map_sink);
  if (odometry && cfg.use_odometry) slam.setOdometry(*odometry);
  if (T_first_second && source.size() > 1)
    slam.setInitialMotion(*T_first_second, source.time(1) - source.time(0));
  const std::size_t n = source.size();
  const std::size_t stride = static_cast<std::size_t>(std::max(1, cfg.scan_stride));
  std::size_t missing = 0;
  for (std::size_t i = 0; i < n;) {
    Scan scan;
    bool ok = true;
    try {
      scan = source.scan(i);
    } catch (const std::exception& e) {
      ok = false;
      if (missing++ < 5) logWarn(std::string("scan ") + std::to_string(i) + ": " + e.what() +
                                 " (predicting with constant velocity)");
    }
    if (ok) {
      scan.t = source.time(i);
      slam.addScan(scan);
    } else {
      slam.addMissing(source.time(i));
    }
    if (progress) progress(i + 1, n);
    // Every scan while turning fast or just after a failure, else every stride-th.
    i += slam.wantsEveryScan() ? 1 : stride;
  }
  if (missing > 5) logWarn(std::to_string(missing) + " scans could not be read in total");
  return slam.finish();
}

}  // namespace slamroute::evaluate
