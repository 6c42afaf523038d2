// Drive-level evaluation: ground truth in, SLAM, metrics and output files out.
#include "slamroute/evaluate/Evaluate.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <optional>
#include <set>

#include "EvaluationSummary.hpp"
#include "slamroute/core/AtomicFile.hpp"
#include "slamroute/core/DriveFolder.hpp"
#include "slamroute/core/Log.hpp"
#include "slamroute/core/OdometrySpec.hpp"
#include "slamroute/core/StagingDir.hpp"
#include "slamroute/core/SumoCoverage.hpp"
#include "slamroute/core/SumoNet.hpp"
#include "slamroute/evaluate/MapAccuracy.hpp"
#include "slamroute/evaluate/MapOutput.hpp"
#include "slamroute/evaluate/MotionChecks.hpp"
#include "slamroute/evaluate/Output.hpp"
#include "slamroute/evaluate/StridedScanSource.hpp"

namespace slamroute::evaluate {
namespace fs = std::filesystem;
namespace {

/// Reads only the LidarSpec keys present; ignores the rest (noise settings etc.).
struct LenientLoader {
  YAML::Node node;
  template <class T>
  void field(const char* key, T& v, const char*) {
    if (node[key]) v = node[key].as<T>();
  }
};

/// The primary coverage figure: directed SUMO edges of the drivable part driven, and the drive's
/// length in SUMO, from the edge sequence the vehicle drove (SumoCoverage.hpp).
SumoCoverage directedCoverage(const SumoNet& net, const std::vector<PoseEdge>& pose_edges) {
  std::vector<std::string> driven;
  for (const auto& pe : pose_edges)
    if (!pe.edge.empty() && pe.edge[0] != ':' && (driven.empty() || driven.back() != pe.edge))
      driven.push_back(pe.edge);
  return sumoCoverage(net, driven);
}

/// Passenger edges of the net named in world.yaml that `pose_edges` visit (the note says why the
/// net is unknown when it is).
EdgeCoverage edgeCoverage(const fs::path& drive, const std::vector<PoseEdge>& pose_edges) {
  EdgeCoverage c;
  std::set<std::string> visited;
  for (const auto& pe : pose_edges)
    if (!pe.edge.empty() && pe.edge[0] != ':') visited.insert(pe.edge);
  c.edges_visited = static_cast<long long>(visited.size());
  const fs::path world = drive / drive_files::kWorld;
  if (!fs::exists(world)) {
    c.note = "no world.yaml: net unknown";
    return c;
  }
  const YAML::Node y = YAML::LoadFile(world.string());
  std::string net;
  for (const char* k : {"net", "net_path", "network"})
    if (y[k] && y[k].IsScalar()) net = y[k].as<std::string>();
  if (net.empty()) {
    c.note = "world.yaml names no net";
    return c;
  }
  fs::path np(net);
  if (np.is_relative() && !fs::exists(np)) np = drive / np;
  if (!fs::exists(np)) {
    c.note = "net " + net + " not found";
    return c;
  }
  const SumoNet sn = SumoNet::read(np);
  c.directed = directedCoverage(sn, pose_edges);
  long long total = 0, hit = 0;
  for (const auto& e : sn.edges) {
    if (e.isInternal() || !e.allowsPassenger()) continue;
    ++total;
    hit += static_cast<long long>(visited.count(e.id));
  }
  c.edges_total = total;
  if (total > 0)
    c.coverage_edge_pct = 100.0 * static_cast<double>(hit) / static_cast<double>(total);
  return c;
}

/// Length-weighted mean drift per label over edges driven >= 20 m (shorter pieces: noise).
std::map<std::string, LabelDrift> driftByLabel(const std::vector<EdgeError>& rows,
                                               const std::map<std::string, std::string>& labels) {
  std::map<std::string, LabelDrift> sums;  // label -> length and length-weighted sums
  for (const auto& r : rows) {
    const auto it = labels.find(r.edge);
    if (it == labels.end() || !std::isfinite(r.drift_pct) || r.length_m < 20.0) continue;
    LabelDrift& s = sums[it->second];
    s.driven_m += r.length_m;
    s.drift_pct += r.drift_pct * r.length_m;
    s.window_drift_pct += r.window_drift_pct * r.length_m;
  }
  for (auto& [label, s] : sums) {
    s.drift_pct /= s.driven_m;
    s.window_drift_pct /= s.driven_m;
  }
  return sums;
}

}  // namespace

LidarSpec readSensorSpec(const fs::path& path) {
  if (!fs::exists(path)) throw std::runtime_error(path.string() + ": sensor settings not found");
  YAML::Node y;
  try {
    y = YAML::LoadFile(path.string());
  } catch (const YAML::Exception&) {
    throw std::runtime_error(path.string() + ": not valid YAML");
  }
  LidarSpec spec;
  auto load = [&](const YAML::Node& n) {
    LenientLoader l{n};
    try {
      visitFields(l, spec);
    } catch (const YAML::Exception&) {
      throw std::runtime_error(path.string() + ": a LidarSpec value has the wrong type");
    }
  };
  if (y.IsMap() && y["channels"]) {
    load(y);
    return spec;
  }
  if (y.IsMap())
    for (const auto& kv : y)
      if (kv.second.IsMap() && kv.second["channels"]) {
        load(kv.second);
        return spec;
      }
  logWarn(path.string() + ": no LidarSpec found, using the paper's 64-channel default");
  return spec;
}

MetricsOptions metricsOptions(const Config& cfg) {
  MetricsOptions o;
  o.max_dt_s = cfg.metrics.assoc_max_dt_s;
  o.rpe_lengths_m = cfg.metrics.rpe_lengths_m;
  o.segment_m = cfg.metrics.rpe_segment_m;
  o.step_frames = cfg.metrics.rpe_step_frames;
  return o;
}

double evaluationDiskGb(double route_km, const Config& cfg) {
  // Measured: Ingolstadt postman 74.5 km, map.pcd 488 MB and ~1.7 GB of clouds (36,479
  // keyframes); default city 14.9 km, 275 MB of clouds. The map's tiles wait in a file of
  // map.pcd's size until map.pcd is written (PcdWriter), by when the clouds' file is gone: the
  // peak is the clouds + the map, or twice the map with the clouds in memory.
  const double map = 0.0066, clouds = 0.023;
  return std::max(0.0, route_km) * (cfg.output.keyframe_clouds_on_disk ? clouds + map : 2 * map) *
         1.1;
}

namespace {

/// Warns when `dir` (the staging folder of `out`) has less free disk than evaluationDiskGb.
void warnIfShortOfDisk(const fs::path& dir, const fs::path& out, double km, const Config& cfg) {
  const double need = evaluationDiskGb(km, cfg);
  std::error_code ec;
  const fs::space_info sp = fs::space(dir, ec);
  if (ec || static_cast<double>(sp.available) >= need * 1e9) return;
  char buf[200];
  std::snprintf(buf, sizeof buf,
                "evaluate: %s has %.2f GB free; a %.1f km drive needs ~%.2f GB there", out.c_str(),
                static_cast<double>(sp.available) / 1e9, km, need);
  logWarn(
      std::string(buf) + " (map.pcd" +
      (cfg.output.keyframe_clouds_on_disk ? ", the keyframe clouds while the SLAM runs)" : ")"));
}

}  // namespace

namespace {

/// Where the estimate starts: the ground-truth pose at the first scan (so the estimate is in the
/// world frame) and the ground-truth motion to the second (SUMO vehicles depart at speed; a real
/// crew would take it from wheel odometry). Without ground truth: the identity.
struct StartState {
  Pose3 T0 = Pose3::Identity();
  std::optional<Pose3> V0;
};

StartState startState(const ScanSource& source, const Trajectory& gt, const Config& cfg) {
  const double tol = 0.5 * std::max(cfg.metrics.assoc_max_dt_s, 0.1);
  Trajectory first = {StampedPose{source.time(0), Pose3::Identity()}};
  if (source.size() > 1) first.push_back(StampedPose{source.time(1), Pose3::Identity()});
  const auto p0 = associate(first, gt, tol);
  StartState s;
  s.T0 = !p0.empty() ? p0.front().gt : gt.empty() ? Pose3::Identity() : gt.front().T_world_body;
  if (p0.size() == 2) s.V0 = p0[0].gt.inverse() * p0[1].gt;
  return s;
}

/// Wheel odometry + gyro when the drive recorded them (slamroute drive does), the gyro's
/// standstill bias removed, and the SLAM config weighing the gyro by the drive's own noise
/// figures (odometry.yaml).
struct MotionPrior {
  WheelOdometry odometry;
  GyroBiasResult gyro;
  Config slam_cfg;
};

MotionPrior motionPrior(const fs::path& drive, const Config& cfg) {
  MotionPrior p{{}, {}, cfg};
  const fs::path odo_file = drive / drive_files::kOdometry;
  if (cfg.odometry.use_wheel_odometry && fs::exists(odo_file))
    p.odometry = readOdometryCsv(odo_file);
  if (cfg.odometry.use_wheel_odometry && p.odometry.empty())
    logInfo("evaluate: no " + odo_file.string() +
            ": predicting motion with a constant-velocity model");
  if (p.odometry.empty()) return p;
  if (cfg.odometry.gyro_standstill_mps > 0) {
    p.gyro = removeStandstillGyroBias(p.odometry, cfg.odometry.gyro_standstill_mps,
                                      cfg.odometry.gyro_min_standstill_s,
                                      cfg.odometry.gyro_standstill_margin_s);
    p.odometry = p.gyro.odometry;
    if (p.gyro.standstill_s >= cfg.odometry.gyro_min_standstill_s)
      logInfo("evaluate: gyro bias " +
              std::to_string(p.gyro.final_bias_rad_s * 180.0 / std::numbers::pi) + " deg/s from " +
              std::to_string(static_cast<int>(p.gyro.standstill_s)) + " s of standstill");
  }
  const fs::path spec = drive / drive_files::kOdometrySpec;
  p.slam_cfg.odometry.prior_sigma_deg = yawPriorSigmaDeg(cfg, readOdometrySpec(spec));
  if (p.slam_cfg.odometry.prior_sigma_deg != cfg.odometry.prior_sigma_deg)
    logInfo("evaluate: yaw prior " + std::to_string(p.slam_cfg.odometry.prior_sigma_deg) +
            " deg per 0.1 s from " + spec.string());
  return p;
}

/// What the SLAM run and the motion prior give the result (trajectory figures aside).
EvaluationResult slamFigures(const SlamResult& slam, const MotionPrior& prior, const Config& cfg) {
  EvaluationResult r;
  r.gyro_standstill_s = prior.gyro.standstill_s;
  r.gyro_bias_deg_s = prior.gyro.final_bias_rad_s * 180.0 / std::numbers::pi;
  r.wheel_odometry = !prior.odometry.empty();
  if (r.wheel_odometry) {
    r.odometry_prior_sigma_deg = prior.slam_cfg.odometry.prior_sigma_deg;
    r.wheel_scale = slam.wheel_scale;
    r.imu_pitch_bias_deg = slam.imu_pitch_bias_deg;
  }
  r.scans = static_cast<long long>(slam.trajectory.size());
  r.scan_stride = cfg.input.scan_stride;
  r.keyframes = slam.keyframes;
  r.loop_candidates = slam.loop_candidates;
  r.loops_rejected_correction = slam.loops_rejected;
  r.loops_rejected_ambiguous = slam.loops_ambiguous;
  r.loops = loopRecords(slam);
  r.map_points = static_cast<long long>(slam.map_points);
  const double n = std::max<double>(1.0, static_cast<double>(slam.trajectory.size()));
  r.timing_ms_per_scan = timingMsPerScan(slam.times, n);
  r.scans_per_s = slam.times.total > 0 ? n / slam.times.total : 0.0;
  r.reliability = reliabilityOf(slam);
  return r;
}

/// per_edge.csv (with ground truth) and the drift per label from it, and the net's coverage.
void addPerEdgeFigures(const fs::path& drive, const std::optional<TrajectoryMetrics>& m,
                       const Config& cfg, const std::map<std::string, std::string>& edge_labels,
                       const fs::path& dir, EvaluationResult& r) {
  std::vector<PoseEdge> pose_edges;
  const fs::path pe_path = drive / drive_files::kPoseEdges;
  if (fs::exists(pe_path)) {
    pose_edges = readPoseEdges(pe_path);
    if (m) {
      const std::vector<EdgeError> per_edge =
          perEdgeErrors(*m, pose_edges, cfg.metrics.assoc_max_dt_s);
      writePerEdgeCsv(dir / "per_edge.csv", per_edge);
      if (!edge_labels.empty()) r.drift_by_label = driftByLabel(per_edge, edge_labels);
    }
  }
  r.coverage = edgeCoverage(drive, pose_edges);
}

/// The map against the world mesh, as built and after the ATE's alignment (what is left is the
/// map's own deformation, not where the run started drifting from), and its picture.
void addMapAccuracy(MapOutput& map, const Config& cfg, const fs::path& dir, EvaluationResult& r) {
  const std::optional<MapAccuracy> accuracy = map.accuracy();
  if (!accuracy) return;
  const MapAccuracy aligned = *map.alignedAccuracy();
  r.map =
      MapFigures{accuracy->mean_m, accuracy->median_m, accuracy->p95_m, accuracy->clamped_share};
  r.map_aligned =
      MapFigures{aligned.mean_m, aligned.median_m, aligned.p95_m, aligned.clamped_share};
  r.map_accuracy_max_m = cfg.metrics.map_accuracy_max_m;
  map.writeImage(dir / "map_error_top.png");
}

SlamResult runSlamWithProgress(const ScanSource& source, const StartState& start,
                               const MotionPrior& prior, const fs::path& dir, MapOutput& map) {
  Progress progress("evaluate: SLAM", source.size());
  SlamResult slam = runSlam(
      source, prior.slam_cfg, start.T0, [&](std::size_t d, std::size_t) { progress.update(d); },
      start.V0, prior.odometry.empty() ? nullptr : &prior.odometry,
      prior.slam_cfg.output.keyframe_clouds_on_disk ? dir : fs::path{}, &map);
  progress.finish();
  return slam;
}

}  // namespace

EvaluationResult evaluateDrive(const fs::path& drive, const ScanSource& all_scans,
                               const fs::path& out, const Config& cfg,
                               const std::map<std::string, std::string>& edge_labels) {
  const Trajectory gt = readTum(drive / drive_files::kGroundTruth);
  if (gt.empty())
    throw std::runtime_error((drive / drive_files::kGroundTruth).string() + ": empty");
  return evaluateScans(drive, all_scans, gt, out, cfg, edge_labels);
}

EvaluationResult evaluateScans(const fs::path& drive, const ScanSource& all_scans,
                               const Trajectory& gt, const fs::path& out, const Config& cfg,
                               const std::map<std::string, std::string>& edge_labels) {
  // The window here; the stride (with denser sampling in turns) inside runSlam.
  const StridedScanSource source(all_scans, 1, cfg.input.start_s, cfg.input.end_s);
  if (source.size() == 0)
    throw std::runtime_error(drive.string() + (all_scans.size() == 0
                                                   ? ": the drive has no scans"
                                                   : ": no scans in the time window"));
  const StartState start = startState(source, gt, cfg);
  const MotionPrior prior = motionPrior(drive, cfg);
  // The world mesh (map accuracy), read before the SLAM so that a bad one fails at once.
  const fs::path mesh_path = drive / drive_files::kWorldMesh;
  std::optional<Mesh> mesh;
  if (fs::exists(mesh_path)) mesh = readPly(mesh_path);
  if (!(cfg.output.map_tile_m > 0))
    throw std::invalid_argument("evaluate.output.map_tile_m must be positive");

  // Only now that every input file has been read: a bad one leaves no output folder behind. The
  // outputs are made in a staging folder beside `out` and replace it at the end, so a failed
  // evaluation (a bad pose_edges.csv read after the SLAM, a full disk) leaves no half set and
  // keeps an earlier evaluation's whole; a folder without metrics.json is not overwritten.
  StagingDir staging(out, "metrics.json");
  const fs::path dir = staging.path();
  warnIfShortOfDisk(dir, out, pathLength(gt) / 1000.0, prior.slam_cfg);
  MapOutput map(dir / "map.pcd", mesh ? &*mesh : nullptr, gt.empty() ? nullptr : &gt,
                cfg.metrics.assoc_max_dt_s, cfg.metrics.map_accuracy_max_m,
                cfg.metrics.plot_size_px);
  const SlamResult slam = runSlamWithProgress(source, start, prior, dir, map);
  writeTum(dir / "estimate.tum", slam.trajectory);
  map.commit();

  std::optional<TrajectoryMetrics> m;
  if (!gt.empty()) m = compareTrajectories(slam.trajectory, gt, metricsOptions(cfg));
  EvaluationResult r = slamFigures(slam, prior, cfg);
  if (m) r.trajectory = trajectorySummary(*m);
  addPerEdgeFigures(drive, m, cfg, edge_labels, dir, r);
  addMapAccuracy(map, cfg, dir, r);
  if (m) {
    plotTopView(dir / "trajectory_top.png", *m, cfg.metrics.plot_size_px);
    plotErrorAlongDistance(dir / "error_along_distance.png", *m, cfg.metrics.plot_size_px);
  }
  writeEvaluationJson(dir / "metrics.json", r);
  staging.commit();
  return r;
}

}  // namespace slamroute::evaluate
