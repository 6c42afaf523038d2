// LeGO-LOAM-style SLAM (paper §3.3). LidarSlam::Impl::addScan reads as the pipeline's steps; the
// parts live in evaluate/src/slam/: MotionModel (prediction and plausibility), FrontEnd (deskew,
// range image, features), ScanToScan, ScanToMap (local map), Relocaliser, KeyframeGraph (pose
// graph) and LoopCloser.
#include "slamroute/evaluate/Slam.hpp"

#include <cmath>
#include <numbers>
#include <optional>
#include <stdexcept>

#include "slam/FrontEnd.hpp"
#include "slam/KeyframeGraph.hpp"
#include "slam/LoopCloser.hpp"
#include "slam/MotionModel.hpp"
#include "slam/Relocaliser.hpp"
#include "slam/ScanToMap.hpp"
#include "slam/ScanToScan.hpp"
#include "slam/SlamClock.hpp"
#include "slamroute/core/Log.hpp"
#include "slamroute/core/Yaw.hpp"
#include "slamroute/evaluate/MapTiles.hpp"
#include "slamroute/evaluate/MotionChecks.hpp"

namespace slamroute::evaluate {

using slam::cpuNow;
using slam::cpuSince;

const char* toString(FrameStatus s) {
  switch (s) {
    case FrameStatus::Ok:
      return "ok";
    case FrameStatus::Empty:
      return "empty_scan";
    case FrameStatus::Invalid:
      return "too_few_valid_points";
    case FrameStatus::Missing:
      return "missing_scan";
    case FrameStatus::FewFeatures:
      return "few_features";
    case FrameStatus::Degenerate:
      return "degenerate_geometry";
  }
  return "unknown";
}

namespace {

/// A frame's pose relative to the keyframe before it, so that the pose graph moves it along.
struct FrameRecord {
  double t = 0;
  int keyframe = -1;  ///< -1: before the first keyframe, T_kf_frame is absolute
  Pose3 T_kf_frame = Pose3::Identity();
  FrameStatus status = FrameStatus::Ok;
  double min_eig = 0;
};

/// What the scan-to-map made of one scan.
struct MapStep {
  Pose3 T_world = Pose3::Identity();
  FrameStatus status = FrameStatus::Ok;
  bool failed = false;       ///< no usable registration: the pose is the prediction's
  bool relocalised = false;  ///< recovered by the hypothesis search
  int inliers = 0;
  double min_eig = 0;
};

}  // namespace

struct LidarSlam::Impl {
  Config cfg;
  LidarSpec spec;
  Pose3 T_world_first;
  slam::MotionModel motion{cfg, T_world_first};
  slam::ScanToScan scan_to_scan{cfg};
  slam::ScanToMap scan_to_map{cfg};
  slam::KeyframeGraph graph{cfg};
  slam::LoopCloser loop_closer{cfg, spec.mount_height_m};
  std::vector<FrameRecord> frames;
  MapSink* map_sink = nullptr;  ///< where finish() puts the map (none: SlamResult::map)
  StageTimes times;
  // Tracking state between scans.
  bool tracking = false;                   ///< a first usable scan was taken
  Pose3 T_world_good = Pose3::Identity();  ///< last well-registered frame
  int good_frame = -1;
  bool last_failed = false;      ///< the previous scan failed
  bool check_motion = true;      ///< dynamics check on (off right after a relocalisation,
                                 ///< whose jump makes the next prediction unreliable)
  double dense_until_t = -1e18;  ///< take every scan until then (after a failure) [s]
  double inlier_ref = 0;         ///< recent scan-to-map inlier level (0: none)

  Impl(const Config& c, const LidarSpec& s, const Pose3& T0) : cfg(c), spec(s), T_world_first(T0) {}

  FrameStatus addScan(const Scan& raw) {
    const double t_all = cpuNow();
    std::optional<Scan> fixed = deskew(raw);  // 0. motion compensation
    const Scan& scan = fixed ? *fixed : raw;
    slam::PreparedScan p = slam::prepareScan(scan, spec, cfg, times);  // 1-2. image, features
    if (fixed) redeskew(raw, *fixed, p);  // 0-2 again with the sweep's own step (no odometry)
    FrameStatus s = p.status;
    if (s != FrameStatus::Ok)
      s = addUnusable(scan.t, s);
    else if (!tracking)
      s = startTracking(scan.t, p);
    else
      s = track(scan.t, p);  // 3-5
    times.total += cpuSince(t_all);
    return s;
  }

  /// Steps 3-5 for a scan after the first: scan-to-scan, scan-to-map (relocalising when it
  /// fails), IMU levelling, motion model, keyframe with loop closure.
  FrameStatus track(double t, const slam::PreparedScan& p) {
    const int index = static_cast<int>(frames.size());
    const slam::Prediction step = motion.predictStep(t);
    const bool check = motion.hasVelocity() && check_motion;
    double t0 = cpuNow();
    bool implausible = false;
    const Pose3 T_prev_curr = scanToScan(p, step, check, implausible);  // 3. odometry
    times.odometry += cpuSince(t0);
    t0 = cpuNow();
    MapStep m = scanToMap(p, step, T_world_good * T_prev_curr, check, implausible);  // 4. mapping
    times.mapping += cpuSince(t0);
    m.T_world = motion.levelled(m.T_world, t);  // IMU roll / pitch
    using Outcome = slam::MotionModel::Outcome;
    const Outcome outcome = m.failed        ? Outcome::Failed
                            : m.relocalised ? Outcome::Relocalised
                                            : Outcome::Registered;
    motion.update(outcome, index - good_frame == 1, T_world_good, m.T_world, step.dt);
    if (m.status == FrameStatus::Ok && outcome == Outcome::Registered && index - good_frame == 1)
      motion.measureWheels(T_world_good, m.T_world, step.dt);
    last_failed = m.failed;
    scan_to_scan.setPrevious(p.features);
    T_world_good = m.T_world;
    good_frame = index;
    if (keyframeDue(m)) {  // 5. keyframe + loop
      addKeyframe(t, m.T_world, p);
      m.T_world = graph.back().T_world;  // may have moved in the pose graph
      T_world_good = m.T_world;
    }
    record(t, m.T_world, m.status, m.min_eig);
    return m.status;
  }

  static constexpr double kSweepS = 0.1;  ///< one revolution of the LiDAR [s]

  /// The deskewed scan, or nothing when the scan is used as it is (no copy on the hot path).
  std::optional<Scan> deskew(const Scan& raw) const {
    if (!cfg.features.deskew || !raw.has_point_times) return std::nullopt;
    return slam::deskewed(raw, motion.motionOver(raw.t, kSweepS), kSweepS);
  }

  /// Without wheel odometry: registers the deskewed scan `p` from the prediction and, when that
  /// is believed, deskews `raw` again with the step from the last registered scan to it and
  /// prepares it anew (FeaturesConfig::redeskew_without_odometry).
  void redeskew(const Scan& raw, Scan& fixed, slam::PreparedScan& p) {
    if (!cfg.features.redeskew_without_odometry || motion.hasOdometry() || !tracking ||
        !motion.hasVelocity() || p.status != FrameStatus::Ok)
      return;
    const slam::Prediction step = motion.predictStep(raw.t);
    if (!(step.dt > 0)) return;
    const AlignResult r = scan_to_map.align(p, step.T_world, scan_to_map.options(motion, step));
    if (!slam::enoughMatches(r, cfg.mapping) ||
        !motion.plausibleStep(step.T_world, r.T_target_source, step))
      return;
    const Pose3 sweep = slam::sweepMotionOfStep(T_world_good, r.T_target_source, step.dt, kSweepS);
    fixed = slam::deskewed(raw, sweep, kSweepS);
    p = slam::prepareScan(fixed, spec, cfg, times);
  }

  FrameStatus startTracking(double t, const slam::PreparedScan& p) {
    const Pose3 T = frames.empty() ? T_world_first : motion.predict(t);
    tracking = true;
    scan_to_scan.setPrevious(p.features);
    T_world_good = T;
    good_frame = static_cast<int>(frames.size());
    addKeyframe(t, T, p);
    record(t, graph.back().T_world, FrameStatus::Ok, 1.0);
    return FrameStatus::Ok;
  }

  /// Scan-to-scan from the last good frame; an implausible result falls back to the prediction.
  Pose3 scanToScan(const slam::PreparedScan& p, const slam::Prediction& step, bool check,
                   bool& implausible) const {
    const Pose3 T_prev_pred = T_world_good.inverse() * step.T_world;
    const Pose3 T_prev_curr = scan_to_scan.align(p.features, T_prev_pred);
    implausible = check && !motion.plausibleStep(T_prev_pred, T_prev_curr, step);
    return implausible ? T_prev_pred : T_prev_curr;
  }

  MapStep scanToMap(const slam::PreparedScan& p, const slam::Prediction& step, const Pose3& init,
                    bool check, bool implausible) {
    const AlignOptions fine = scan_to_map.options(motion, step);
    const Pose3 start = scan_to_map.coarse(p, init, fine, motion, step);
    const AlignResult r = scan_to_map.align(p, start, fine);
    MapStep m = judge(p, step, start, r, fine, check, implausible);
    // A sudden drop of the inliers against the recent level means the registration settled in a
    // wrong minimum (e.g. a heading jump): the hypothesis search runs too.
    const bool inlier_drop = inlier_ref > 0 && r.inliers < cfg.relocalise.inlier_drop * inlier_ref;
    check_motion = true;
    if ((m.failed || inlier_drop) && !last_failed)
      dense_until_t = step.t + cfg.input.dense_after_failure_s;
    if ((m.failed || inlier_drop || !motion.hasVelocity()) && searchAllowed(p))
      relocalise(p, step, fine, r, m);
    if (m.failed || inlier_drop || !check_motion || implausible) logFrame(step, r, m, implausible);
    // The level follows rising inlier counts at once and falling ones slowly, so a sudden drop
    // stands out while a gradual change of scenery does not trigger searches.
    if (!m.failed)
      inlier_ref = std::max(static_cast<double>(m.inliers), cfg.relocalise.ref_decay * inlier_ref);
    return m;
  }

  /// Whether the registration `r` from `start` is believed: too few matches (an open street) or,
  /// with wheel odometry, a result beyond the odometry's slack (a sweep smeared by a U-turn):
  /// the prediction, with height, roll and pitch from the planes; without odometry an
  /// implausible jump keeps the start; else the result.
  MapStep judge(const slam::PreparedScan& p, const slam::Prediction& step, const Pose3& start,
                const AlignResult& r, const AlignOptions& fine, bool check,
                bool implausible) const {
    MapStep m;
    m.T_world = start;
    m.status = implausible ? FrameStatus::Degenerate : FrameStatus::Ok;
    m.inliers = r.inliers;
    m.min_eig = r.min_eig_translation;
    const bool few = !slam::enoughMatches(r, cfg.mapping);
    const bool jump = !few && check && !motion.plausibleStep(step.T_world, r.T_target_source, step);
    if (few || jump) {
      m.status = few ? FrameStatus::FewFeatures : FrameStatus::Degenerate;
      m.failed = true;
      // The motion model (odometry, or a car's constant velocity) predicts better than a
      // scan-to-scan match that had even fewer features or an implausible turn to work with.
      if (motion.hasOdometry() || (few && motion.hasVelocity())) m.T_world = step.T_world;
      if (few || motion.hasOdometry()) m.T_world = levelledByPlanes(p, step, m.T_world, fine);
    } else {
      m.T_world = r.T_target_source;
      if (r.min_eig_translation < cfg.mapping.degeneracy_min_eig)
        m.status = FrameStatus::Degenerate;
    }
    return m;
  }

  /// Height, roll and pitch of `T` from the scan's planes alone, when they are plausible.
  Pose3 levelledByPlanes(const slam::PreparedScan& p, const slam::Prediction& step, const Pose3& T,
                         const AlignOptions& fine) const {
    AlignOptions planes_only = fine;
    planes_only.dof_mask = kZ | kRoll | kPitch;
    const AlignResult g = scan_to_map.alignPlanes(p, T, planes_only);
    if (g.plane_matches >= cfg.mapping.min_plane_features &&
        motion.plausibleStep(step.T_world, g.T_target_source, step))
      return g.T_target_source;
    return T;
  }

  /// The search needs edges (in an open field it cannot succeed); with wheel odometry + gyro the
  /// pose may not leave the odometry's slack anyway and the prediction is inside the basin.
  bool searchAllowed(const slam::PreparedScan& p) const {
    const bool searchable = static_cast<int>(p.src_edges.size()) >= cfg.mapping.min_edge_features;
    return cfg.relocalise.enabled && searchable && !motion.hasOdometry();
  }

  void relocalise(const slam::PreparedScan& p, const slam::Prediction& step,
                  const AlignOptions& fine, const AlignResult& r, MapStep& m) {
    const auto found = slam::relocalise(scan_to_map.localMap(), p, step.T_world,
                                        motion.hasVelocity(), fine, r.inliers, cfg);
    if (!found) return;
    m.T_world = found->T_world;
    m.inliers = found->inliers;
    m.status = FrameStatus::Ok;
    m.failed = false;
    m.relocalised = true;
    check_motion = false;
  }

  bool keyframeDue(const MapStep& m) const {
    const Pose3 rel = graph.back().T_world.inverse() * m.T_world;
    const double d = rel.translation().norm();
    if (m.failed) return d > cfg.mapping.failed_keyframe_distance_m;
    return d > cfg.mapping.keyframe_distance_m ||
           rotationAngle(rel) > cfg.mapping.keyframe_angle_deg * std::numbers::pi / 180.0;
  }

  void addKeyframe(double t, const Pose3& T_world, const slam::PreparedScan& p) {
    graph.add(t, static_cast<int>(frames.size()), T_world, p.kf_edges, p.kf_planes,
              p.features.segmented, motion.imuPitchRad(t));
    loop_closer.addPlace(graph, p.features.segmented);
    motion.keyframeAt(T_world.translation());
    bool closed = false;
    if (cfg.loop.enabled) {
      const double t0 = cpuNow();
      closed = loop_closer.tryClose(graph, times);
      times.loop_closure += cpuSince(t0);
    }
    if (closed && graph.estimatesPitchBias()) {
      motion.assumePitchBias(graph.pitchBiasRad());
    } else if (closed) {
      const LoopClosure& l = loop_closer.stats().loops.back();
      motion.measureTilt(l.from_keyframe, l.correction_z_m);
    }
    const double t0 = cpuNow();
    scan_to_map.rebuild(graph, closed || graph.size() == 1);
    times.local_map += cpuSince(t0);
  }

  void record(double t, const Pose3& T_world, FrameStatus s, double min_eig) {
    FrameRecord r;
    r.t = t;
    r.status = s;
    r.min_eig = min_eig;
    r.keyframe = static_cast<int>(graph.size()) - 1;
    r.T_kf_frame = r.keyframe >= 0 ? graph.back().T_world.inverse() * T_world : T_world;
    frames.push_back(r);
    motion.recordFrame(t, T_world);
  }

  FrameStatus addUnusable(double t, FrameStatus s) {
    record(t, frames.empty() ? T_world_first : motion.predict(t), s, 0.0);
    return s;
  }

  void logFrame(const slam::Prediction& step, const AlignResult& r, const MapStep& m,
                bool implausible) const {
    const auto yawDeg = [](const Pose3& T) {
      return std::to_string(yawOf(T) * 180.0 / std::numbers::pi);
    };
    logDebug("t=" + std::to_string(step.t) + " s: " + toString(m.status) +
             (m.failed ? " (failed)" : "") + (check_motion ? "" : " relocalised") +
             (implausible ? " odometry implausible" : "") + ", inliers " +
             std::to_string(r.inliers) + " (recent " +
             std::to_string(static_cast<int>(inlier_ref)) + "), edge/plane matches " +
             std::to_string(r.edge_matches) + "/" + std::to_string(r.plane_matches) + ", yaw " +
             yawDeg(m.T_world) + " deg (predicted " + yawDeg(step.T_world) + ")");
  }

  SlamResult finish();
};

SlamResult LidarSlam::Impl::finish() {
  SlamResult out;
  // The path after the last closure is levelled by the IMU pitch factors too.
  if (graph.estimatesPitchBias() && graph.size() > 1) graph.optimize();
  for (const auto& r : frames) {
    StampedPose sp;
    sp.t = r.t;
    sp.T_world_body = r.keyframe >= 0
                          ? graph.at(static_cast<std::size_t>(r.keyframe)).T_world * r.T_kf_frame
                          : r.T_kf_frame;
    out.trajectory.push_back(sp);
    out.status.push_back(r.status);
    out.min_eig.push_back(r.min_eig);
  }
  // The map: every keyframe's cloud at its optimised pose, voxel-filtered tile by tile into the
  // sink (each keyframe's cloud is freed after its last tile; the run is over).
  std::vector<MapKeyframe> map_kfs;
  map_kfs.reserve(graph.size());
  for (std::size_t k = 0; k < graph.size(); ++k)
    map_kfs.push_back({graph.at(k).cloud, graph.at(k).T_world});
  CollectedMap collected;
  MapSink& sink = map_sink ? *map_sink : collected;
  sink.estimate(out.trajectory);
  std::optional<Progress> progress;  // the tiles are counted inside
  out.map_points =
      buildMapByTiles(graph.clouds(), map_kfs, cfg.output.map_voxel_m, cfg.output.map_tile_m, sink,
                      [&](std::size_t done, std::size_t total) {
                        if (!progress) progress.emplace("SLAM: map tiles", total);
                        progress->update(done);
                      });
  if (progress) progress->finish();
  out.map = std::move(collected.map);
  if (graph.clouds().onDisk())
    logInfo("SLAM: the keyframes' clouds took " +
            std::to_string(graph.clouds().bytesOnDisk() / 1000000) + " MB in a temporary file (" +
            std::to_string(graph.size()) + " keyframes)");
  const slam::LoopStats& ls = loop_closer.stats();
  out.loops = ls.loops;
  out.loop_candidates = ls.candidates;
  out.loops_rejected = ls.rejected;
  out.loops_ambiguous = ls.ambiguous;
  out.wheel_scale = motion.wheelScale();
  out.imu_pitch_bias_deg = motion.pitchBiasRad() * 180.0 / std::numbers::pi;
  out.keyframes = static_cast<int>(graph.size());
  out.times = times;
  return out;
}

LidarSlam::LidarSlam(const Config& cfg, const LidarSpec& spec, const Pose3& T_world_first)
    : impl_(std::make_unique<Impl>(cfg, spec, T_world_first)) {}
LidarSlam::~LidarSlam() = default;
void LidarSlam::setMapSink(MapSink& sink) { impl_->map_sink = &sink; }
void LidarSlam::keepCloudsOnDisk(const std::filesystem::path& dir) {
  impl_->graph.keepCloudsOnDisk(dir);
}
void LidarSlam::setInitialMotion(const Pose3& T_first_second, double dt_s) {
  impl_->motion.setInitialMotion(T_first_second, dt_s);
}
FrameStatus LidarSlam::addScan(const Scan& scan) { return impl_->addScan(scan); }
FrameStatus LidarSlam::addMissing(double t) { return impl_->addUnusable(t, FrameStatus::Missing); }
Pose3 LidarSlam::currentPose() const { return impl_->motion.lastPose(); }
void LidarSlam::setOdometry(WheelOdometry odometry) {
  impl_->loop_closer.setPlaceSearch(odometry.empty());
  impl_->motion.setOdometry(std::move(odometry));
}
double LidarSlam::turnRateDegPerS() const { return impl_->motion.turnRateDegPerS(); }
bool LidarSlam::wantsEveryScan() const {
  const Impl& s = *impl_;
  if (s.frames.empty()) return false;
  if (s.frames.back().t < s.dense_until_t) return true;
  return s.cfg.input.dense_turn_rate_deg_s > 0 &&
         turnRateDegPerS() > s.cfg.input.dense_turn_rate_deg_s;
}
SlamResult LidarSlam::finish() { return impl_->finish(); }

SlamResult runSlam(const ScanSource& source, const Config& cfg, const Pose3& T_world_first,
                   const std::function<void(std::size_t, std::size_t)>& progress,
                   const std::optional<Pose3>& T_first_second, const WheelOdometry* odometry,
                   const std::filesystem::path& cloud_dir, MapSink* map_sink) {
  LidarSlam slam(cfg, source.spec(), T_world_first);
  if (!cloud_dir.empty()) slam.keepCloudsOnDisk(cloud_dir);
  if (map_sink) slam.setMapSink(*map_sink);
  if (odometry && cfg.odometry.use_wheel_odometry) slam.setOdometry(*odometry);
  if (T_first_second && source.size() > 1)
    slam.setInitialMotion(*T_first_second, source.time(1) - source.time(0));
  const std::size_t n = source.size();
  const std::size_t stride = static_cast<std::size_t>(std::max(1, cfg.input.scan_stride));
  std::size_t missing = 0;
  for (std::size_t i = 0; i < n;) {
    Scan scan;
    bool ok = true;
    try {
      scan = source.scan(i);
    } catch (const std::exception& e) {
      ok = false;
      if (missing++ < 5)
        logWarn(std::string("scan ") + std::to_string(i) + ": " + e.what() +
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
    i = nextScanIndex(i, stride, slam.wantsEveryScan());
  }
  if (missing > 5) logWarn(std::to_string(missing) + " scans could not be read in total");
  return slam.finish();
}

}  // namespace slamroute::evaluate
