// Drive-level evaluation: ground truth in, SLAM, metrics and output files out.
#include "slamroute/evaluate/Evaluate.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>
#include <set>

#include "slamroute/core/Yaw.hpp"
#include "slamroute/core/AtomicFile.hpp"
#include "slamroute/core/DriveFolder.hpp"
#include "slamroute/core/Log.hpp"
#include "slamroute/core/StagingDir.hpp"
#include "slamroute/core/OdometrySpec.hpp"
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

double nanToNull(double v) { return v; }  // nlohmann writes NaN as null

/// The primary coverage figure: directed SUMO edges of the drivable part driven, and the drive's
/// length in SUMO, from the edge sequence the vehicle drove (SumoCoverage.hpp).
void addDirectedCoverage(const SumoNet& net, const std::vector<PoseEdge>& pose_edges,
                         nlohmann::json& j) {
  std::vector<std::string> driven;
  for (const auto& pe : pose_edges)
    if (!pe.edge.empty() && pe.edge[0] != ':' && (driven.empty() || driven.back() != pe.edge))
      driven.push_back(pe.edge);
  sumoCoverageToJson(sumoCoverage(net, driven), j);
}

/// coverage_edge_pct: visited passenger edges / passenger edges of the net named in world.yaml.
void addCoverage(const fs::path& drive, const std::vector<PoseEdge>& pose_edges, nlohmann::json& j) {
  j["coverage_edge_pct"] = nullptr;
  std::set<std::string> visited;
  for (const auto& pe : pose_edges)
    if (!pe.edge.empty() && pe.edge[0] != ':') visited.insert(pe.edge);
  j["edges_visited"] = visited.size();
  const fs::path world = drive / drive_files::kWorld;
  if (!fs::exists(world)) {
    j["coverage_note"] = "no world.yaml: net unknown";
    return;
  }
  const YAML::Node y = YAML::LoadFile(world.string());
  std::string net;
  for (const char* k : {"net", "net_path", "network"})
    if (y[k] && y[k].IsScalar()) net = y[k].as<std::string>();
  if (net.empty()) {
    j["coverage_note"] = "world.yaml names no net";
    return;
  }
  fs::path np(net);
  if (np.is_relative() && !fs::exists(np)) np = drive / np;
  if (!fs::exists(np)) {
    j["coverage_note"] = "net " + net + " not found";
    return;
  }
  const SumoNet sn = SumoNet::read(np);
  addDirectedCoverage(sn, pose_edges, j);
  std::size_t total = 0, hit = 0;
  for (const auto& e : sn.edges) {
    if (e.isInternal() || !e.allowsPassenger()) continue;
    ++total;
    hit += visited.count(e.id);
  }
  j["edges_total"] = total;
  if (total > 0) j["coverage_edge_pct"] = 100.0 * static_cast<double>(hit) / static_cast<double>(total);
}

/// Length-weighted mean drift per label over edges driven >= 20 m (shorter pieces: noise).
nlohmann::json driftByLabel(const std::vector<EdgeError>& rows, const std::map<std::string, std::string>& labels) {
  std::map<std::string, std::pair<double, double>> acc;  // label -> (sum drift*len, sum len)
  for (const auto& r : rows) {
    const auto it = labels.find(r.edge);
    if (it == labels.end() || !std::isfinite(r.drift_pct) || r.length_m < 20.0) continue;
    acc[it->second].first += r.drift_pct * r.length_m;
    acc[it->second].second += r.length_m;
  }
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [label, dl] : acc) j[label] = {{"driven_m", dl.second}, {"drift_pct", dl.first / dl.second}};
  return j;
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

nlohmann::json trajectoryJson(const TrajectoryMetrics& m) {
  nlohmann::json j;
  j["poses_matched"] = m.pairs.size();
  j["ate_rmse_m"] = m.ate.rmse_m;
  j["ate_mean_m"] = m.ate.mean_m;
  j["ate_median_m"] = m.ate.median_m;
  j["ate_max_m"] = m.ate.max_m;
  j["rpe_trans_pct"] = nanToNull(m.rpe_kitti.trans_pct);
  j["rpe_rot_deg_per_m"] = nanToNull(m.rpe_kitti.rot_deg_per_m);
  j["rpe_segments"] = m.rpe_kitti.segments;
  j["rpe_segment_m"] = m.segment_m;
  j["rpe_segment_trans_pct"] = nanToNull(m.rpe_segment.trans_pct);
  j["rpe_segment_rot_deg_per_m"] = nanToNull(m.rpe_segment.rot_deg_per_m);
  j["rpe_segment_count"] = m.rpe_segment.segments;
  j["route_length_m"] = m.route_length_m;
  j["evaluated_length_m"] = m.distance_m.empty() ? 0.0 : m.distance_m.back();
  const Eigen::Quaterniond q(m.T_gt_est.rotation());
  const Vec3 t = m.T_gt_est.translation();
  j["alignment_T_gt_est"] = {{"t", {t.x(), t.y(), t.z()}}, {"q_xyzw", {q.x(), q.y(), q.z(), q.w()}}};
  return j;
}

nlohmann::json reliabilityJson(const SlamResult& r) {
  nlohmann::json j;
  std::map<std::string, int> by_reason;
  nlohmann::json stretches = nlohmann::json::array();
  std::size_t bad = 0;
  for (std::size_t i = 0; i < r.status.size();) {
    if (r.status[i] == FrameStatus::Ok) {
      ++i;
      continue;
    }
    std::size_t k = i;
    std::map<std::string, int> reasons;
    while (k < r.status.size() && r.status[k] != FrameStatus::Ok) ++reasons[toString(r.status[k++])];
    bad += k - i;
    for (const auto& [name, c] : reasons) by_reason[name] += c;
    nlohmann::json s = {{"first_scan", i}, {"last_scan", k - 1},
                        {"t_start", r.trajectory[i].t}, {"t_end", r.trajectory[k - 1].t},
                        {"reasons", reasons}};
    stretches.push_back(s);
    i = k;
  }
  j["unreliable_scans"] = bad;
  j["unreliable_share"] = r.status.empty() ? 0.0 : static_cast<double>(bad) / static_cast<double>(r.status.size());
  j["by_reason"] = by_reason;
  j["stretches"] = stretches;
  j["reliable"] = bad == 0;
  return j;
}

double evaluationDiskGb(double route_km, const Config& cfg) {
  // Measured: Ingolstadt postman 74.5 km, map.pcd 488 MB and ~1.7 GB of clouds (36,479
  // keyframes); default city 14.9 km, 275 MB of clouds. The map's tiles wait in a file of
  // map.pcd's size until map.pcd is written (PcdWriter), by when the clouds' file is gone: the
  // peak is the clouds + the map, or twice the map with the clouds in memory.
  const double map = 0.0066, clouds = 0.023;
  return std::max(0.0, route_km) * (cfg.output.keyframe_clouds_on_disk ? clouds + map : 2 * map) * 1.1;
}

namespace {

/// Warns when `dir` (the staging folder of `out`) has less free disk than evaluationDiskGb.
void warnIfShortOfDisk(const fs::path& dir, const fs::path& out, double km, const Config& cfg) {
  const double need = evaluationDiskGb(km, cfg);
  std::error_code ec;
  const fs::space_info sp = fs::space(dir, ec);
  if (ec || static_cast<double>(sp.available) >= need * 1e9) return;
  char buf[200];
  std::snprintf(buf, sizeof buf, "evaluate: %s has %.2f GB free; a %.1f km drive needs ~%.2f GB there", out.c_str(),
                static_cast<double>(sp.available) / 1e9, km, need);
  logWarn(std::string(buf) + " (map.pcd" + (cfg.output.keyframe_clouds_on_disk ? ", the keyframe clouds while the SLAM runs)" : ")"));
}

}  // namespace

nlohmann::json evaluateDrive(const fs::path& drive, const ScanSource& all_scans, const fs::path& out,
                             const Config& cfg, const std::map<std::string, std::string>& edge_labels) {
  const Trajectory gt = readTum(drive / drive_files::kGroundTruth);
  if (gt.empty()) throw std::runtime_error((drive / drive_files::kGroundTruth).string() + ": empty");
  return evaluateScans(drive, all_scans, gt, out, cfg, edge_labels);
}

nlohmann::json evaluateScans(const fs::path& drive, const ScanSource& all_scans,
                             const Trajectory& gt, const fs::path& out, const Config& cfg,
                             const std::map<std::string, std::string>& edge_labels) {
  // The window here; the stride (with denser sampling in turns) inside runSlam.
  const StridedScanSource source(all_scans, 1, cfg.input.start_s, cfg.input.end_s);
  if (source.size() == 0)
    throw std::runtime_error(drive.string() + (all_scans.size() == 0 ? ": the drive has no scans"
                                                                     : ": no scans in the time window"));
  // Initial pose = the ground-truth pose at the first scan (documented in metrics.json).
  // Initial motion = the ground-truth motion between the first two scans (SUMO vehicles depart
  // at speed; a real crew would take it from wheel odometry).
  const double tol = 0.5 * std::max(cfg.metrics.assoc_max_dt_s, 0.1);
  Trajectory first = {StampedPose{source.time(0), Pose3::Identity()}};
  if (source.size() > 1) first.push_back(StampedPose{source.time(1), Pose3::Identity()});
  const auto p0 = associate(first, gt, tol);
  // Without ground truth the estimate starts at the identity.
  const Pose3 T0 = !p0.empty()   ? p0.front().gt
                   : gt.empty() ? Pose3::Identity()
                                : gt.front().T_world_body;
  std::optional<Pose3> V0;
  if (p0.size() == 2) V0 = p0[0].gt.inverse() * p0[1].gt;

  // Wheel odometry + gyro, when the drive recorded them (slamroute drive does).
  WheelOdometry odometry;
  const fs::path odo_file = drive / drive_files::kOdometry;
  if (cfg.odometry.use_wheel_odometry && fs::exists(odo_file)) odometry = readOdometryCsv(odo_file);
  if (cfg.odometry.use_wheel_odometry && odometry.empty())
    logInfo("evaluate: no " + odo_file.string() + ": predicting motion with a constant-velocity model");
  GyroBiasResult gyro;
  if (!odometry.empty() && cfg.odometry.gyro_standstill_mps > 0) {
    gyro = removeStandstillGyroBias(odometry, cfg.odometry.gyro_standstill_mps, cfg.odometry.gyro_min_standstill_s,
                                    cfg.odometry.gyro_standstill_margin_s);
    odometry = gyro.odometry;
    if (gyro.standstill_s >= cfg.odometry.gyro_min_standstill_s)
      logInfo("evaluate: gyro bias " + std::to_string(gyro.final_bias_rad_s * 180.0 / std::numbers::pi) +
              " deg/s from " + std::to_string(static_cast<int>(gyro.standstill_s)) + " s of standstill");
  }

  // The gyro weighed by its own noise figures when the drive states them (odometry.yaml).
  Config slam_cfg = cfg;
  if (!odometry.empty()) {
    slam_cfg.odometry.prior_sigma_deg =
        yawPriorSigmaDeg(cfg, readOdometrySpec(drive / drive_files::kOdometrySpec));
    if (slam_cfg.odometry.prior_sigma_deg != cfg.odometry.prior_sigma_deg)
      logInfo("evaluate: yaw prior " + std::to_string(slam_cfg.odometry.prior_sigma_deg) + " deg per 0.1 s from " +
              (drive / drive_files::kOdometrySpec).string());
  }

  // The world mesh (map accuracy), read before the SLAM so that a bad one fails at once.
  const fs::path mesh_path = drive / drive_files::kWorldMesh;
  std::optional<Mesh> mesh;
  if (fs::exists(mesh_path)) mesh = readPly(mesh_path);
  if (!(cfg.output.map_tile_m > 0)) throw std::invalid_argument("evaluate.output.map_tile_m must be positive");

  // Only now that every input file has been read: a bad one leaves no output folder behind. The
  // outputs are made in a staging folder beside `out` and replace it at the end, so a failed
  // evaluation (a bad pose_edges.csv read after the SLAM, a full disk) leaves no half set and
  // keeps an earlier evaluation's whole; a folder without metrics.json is not overwritten.
  StagingDir staging(out, "metrics.json");
  const fs::path dir = staging.path();
  warnIfShortOfDisk(dir, out, pathLength(gt) / 1000.0, slam_cfg);
  MapOutput map(dir / "map.pcd", mesh ? &*mesh : nullptr, gt.empty() ? nullptr : &gt,
                cfg.metrics.assoc_max_dt_s, cfg.metrics.map_accuracy_max_m,
                cfg.metrics.plot_size_px);
  Progress progress("evaluate: SLAM", source.size());
  SlamResult slam = runSlam(source, slam_cfg, T0, [&](std::size_t d, std::size_t) { progress.update(d); }, V0,
                            odometry.empty() ? nullptr : &odometry,
                            slam_cfg.output.keyframe_clouds_on_disk ? dir : fs::path{}, &map);
  progress.finish();
  writeTum(dir / "estimate.tum", slam.trajectory);
  map.commit();

  std::optional<TrajectoryMetrics> m;
  if (!gt.empty()) m = compareTrajectories(slam.trajectory, gt, metricsOptions(cfg));
  nlohmann::json j = m ? trajectoryJson(*m) : nlohmann::json::object();
  if (!m) j["trajectory_metrics"] = "skipped: no ground truth";
  j["initial_pose"] = m ? "ground-truth pose of the first scan and motion to the second (estimate "
                          "is in the world frame)"
                        : "identity (no ground truth)";
  j["gyro_standstill_s"] = gyro.standstill_s;
  j["gyro_bias_deg_s"] = gyro.final_bias_rad_s * 180.0 / std::numbers::pi;
  j["motion_prior"] = odometry.empty() ? "constant velocity" : "wheel odometry + gyro (odometry.csv)";
  if (!odometry.empty()) j["odometry_prior_sigma_deg"] = slam_cfg.odometry.prior_sigma_deg;
  j["scans"] = slam.trajectory.size();
  j["scan_stride"] = cfg.input.scan_stride;
  j["keyframes"] = slam.keyframes;
  j["loop_closures"] = slam.loops.size();
  j["loop_closures_by_place"] =
      std::count_if(slam.loops.begin(), slam.loops.end(), [](const LoopClosure& l) { return l.by_place; });
  j["loop_candidates"] = slam.loop_candidates;
  j["loops_rejected_correction"] = slam.loops_rejected;
  j["loops_rejected_ambiguous"] = slam.loops_ambiguous;
  nlohmann::json loops = nlohmann::json::array();
  for (const auto& l : slam.loops)
    loops.push_back({{"old_keyframe", l.from_keyframe}, {"new_keyframe", l.to_keyframe},
                     {"t_old", l.t_old}, {"t_new", l.t_new}, {"fitness_m2", l.fitness_m2},
                     {"correction_m", l.correction_m}, {"by_place", l.by_place},
                     {"t_old_new", {l.T_old_new.translation().x(), l.T_old_new.translation().y(),
                                    l.T_old_new.translation().z()}},
                     {"yaw_old_new_deg", yawOf(l.T_old_new) *
                                             180.0 / std::numbers::pi}});
  j["loops"] = loops;

  // per-edge drift + coverage
  std::vector<PoseEdge> pose_edges;
  const fs::path pe_path = drive / drive_files::kPoseEdges;
  if (fs::exists(pe_path)) {
    pose_edges = readPoseEdges(pe_path);
    if (m) {
      const std::vector<EdgeError> per_edge =
          perEdgeErrors(*m, pose_edges, cfg.metrics.assoc_max_dt_s);
      writePerEdgeCsv(dir / "per_edge.csv", per_edge);
      if (!edge_labels.empty()) j["drift_by_label"] = driftByLabel(per_edge, edge_labels);
    }
  }
  addCoverage(drive, pose_edges, j);

  // map accuracy against the world mesh
  j["map_points"] = slam.map_points;
  j["map_mean_dist_m"] = nullptr;
  j["map_p95_dist_m"] = nullptr;
  if (const std::optional<MapAccuracy> accuracy = map.accuracy()) {
    const MapAccuracy& acc = *accuracy;
    j["map_mean_dist_m"] = acc.mean_m;
    j["map_median_dist_m"] = acc.median_m;
    j["map_p95_dist_m"] = acc.p95_m;
    j["map_far_share"] = acc.clamped_share;
    j["map_accuracy_max_m"] = cfg.metrics.map_accuracy_max_m;  // distances are clamped here
    // The same after the estimate's alignment onto the ground truth (the ATE's T_gt_est): what is
    // left is the map's own deformation, not where the run started drifting from.
    const MapAccuracy aligned = *map.alignedAccuracy();
    j["map_aligned_mean_dist_m"] = aligned.mean_m;
    j["map_aligned_median_dist_m"] = aligned.median_m;
    j["map_aligned_p95_dist_m"] = aligned.p95_m;
    j["map_aligned_far_share"] = aligned.clamped_share;
    map.writeImage(dir / "map_error_top.png");
  }

  const StageTimes& t = slam.times;
  const double n = std::max<double>(1.0, static_cast<double>(slam.trajectory.size()));
  j["timing_ms_per_scan"] = {{"projection", 1e3 * t.projection / n}, {"ground", 1e3 * t.ground / n},
                             {"clustering", 1e3 * t.clustering / n}, {"features", 1e3 * t.features / n},
                             {"odometry", 1e3 * t.odometry / n}, {"mapping", 1e3 * t.mapping / n}, {"local_map", 1e3 * t.local_map / n},
                             {"loop_closure", 1e3 * t.loop_closure / n},
                             {"pose_graph", 1e3 * t.pose_graph / n}, {"total", 1e3 * t.total / n}};
  j["scans_per_s"] = t.total > 0 ? n / t.total : 0.0;
  j["reliability"] = reliabilityJson(slam);

  if (m) {
    plotTopView(dir / "trajectory_top.png", *m, cfg.metrics.plot_size_px);
    plotErrorAlongDistance(dir / "error_along_distance.png", *m, cfg.metrics.plot_size_px);
  }
  writeFileAtomic(dir / "metrics.json", j.dump(2) + "\n");
  staging.commit();
  return j;
}

}  // namespace slamroute::evaluate
