// `slamroute evaluate --drive DIR --out DIR2`: paper §3.3 — LeGO-LOAM-style SLAM on a drive's
// scans, then ATE/RPE/per-edge/map metrics against the drive's ground truth.
// `slamroute evaluate --kitti SEQ_DIR --out DIR2`: the same on a KITTI odometry sequence
// (core/KittiSequence.hpp), against its poses.txt when it has one.
#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>

#include "Commands.hpp"
#include "EvaluateCompleteness.hpp"
#include "EvaluateFleet.hpp"
#include "slamroute/core/DriveFolder.hpp"
#include "slamroute/core/FleetDrive.hpp"
#include "slamroute/core/KittiSequence.hpp"
#include "slamroute/core/Log.hpp"
#include "slamroute/core/SumoNet.hpp"
#include "slamroute/evaluate/DriveChecks.hpp"
#include "slamroute/evaluate/Evaluate.hpp"
#include "slamroute/simulate/Drive.hpp"
#include "slamroute/simulate/SimulatedScanSource.hpp"
#include "slamroute/simulate/World.hpp"

namespace slamroute::cli {
namespace {

namespace fs = std::filesystem;

/// Street kind (rich / wall / open) per SUMO edge of a simulated drive, so that metrics.json
/// shows the drift per kind of street; empty for a drive without world.yaml.
std::map<std::string, std::string> streetKinds(const fs::path& drive) {
  std::map<std::string, std::string> kinds;
  if (!fs::exists(drive / drive_files::kWorld)) return kinds;
  const simulate::DriveWorldFile wf = simulate::readDriveWorldFile(drive);
  const SumoNet net = SumoNet::read(wf.net);
  const simulate::World world = simulate::World::build(net, wf.world, wf.seed);
  for (const auto& e : net.edges) {
    if (e.isInternal()) continue;
    try {
      kinds[e.id] = simulate::streetKindName(world.streetKind(e.id));
    } catch (const std::exception&) {
    }
  }
  return kinds;
}

evaluate::EvaluationResult evaluateDriveFolder(const std::string& drive_dir, const std::string& out,
                                               const evaluate::Config& cfg,
                                               const explore::Config& explore) {
  const fs::path drive(drive_dir);
  if (!fs::is_directory(drive)) throw std::invalid_argument(drive_dir + ": not a drive folder");
  if (!fs::exists(drive / drive_files::kGroundTruth))
    throw std::invalid_argument(drive_dir + ": no " + drive_files::kGroundTruth +
                                " (not a drive folder?)");
  const LidarSpec spec = evaluate::readSensorSpec(drive / drive_files::kSensor);
  std::unique_ptr<ScanSource> source;
  if (fs::is_directory(drive / drive_files::kScanDir)) {
    source = std::make_unique<KittiScanSource>(drive / drive_files::kScanDir, spec);
  } else {
    logInfo("evaluate: no scans/ in the drive, regenerating scans with the simulator");
    source = std::make_unique<simulate::SimulatedScanSource>(drive);
  }
  evaluate::checkDriveFiles(drive, *source);
  logInfo("evaluate: " + std::to_string(source->size()) + " scans from " + drive_dir);
  evaluate::EvaluationResult r =
      evaluate::evaluateDrive(drive, *source, out, cfg, streetKinds(drive));
  addMapCompleteness(drive, *source, out, explore, r);
  return r;
}

/// A KITTI sequence has no wheel odometry; without poses.txt there is nothing to measure against.
evaluate::EvaluationResult evaluateKittiSequence(const std::string& seq_dir,
                                                 const std::string& sensor, const std::string& out,
                                                 const evaluate::Config& cfg) {
  const KittiSequence seq = readKittiSequence(seq_dir, lidarPreset(sensor));
  logInfo("evaluate: " + std::to_string(seq.scans->size()) + " scans from " + seq_dir +
          " (sensor " + sensor + ")");
  if (seq.ground_truth.empty())
    logInfo("evaluate: " + seq_dir + " has no " + kitti_files::kPoses +
            ": trajectory metrics skipped, the estimate starts at the identity");
  return evaluate::evaluateScans(seq_dir, *seq.scans, seq.ground_truth, out, cfg);
}

/// One line of what was measured; figures as metrics.json spells them.
void printSummary(const evaluate::EvaluationResult& r, const std::string& out) {
  using nlohmann::json;
  const json loops(r.loops.size());
  if (!r.trajectory) {
    std::cout << "no ground truth: trajectory metrics skipped; " << json(r.scans)
              << " scans, loop closures " << loops << " -> " << out << "\n";
    return;
  }
  const evaluate::TrajectorySummary& t = *r.trajectory;
  std::cout << "ATE rmse " << json(t.ate_rmse_m) << " m, RPE " << json(t.rpe_trans_pct)
            << " %, end drift " << json(t.end_drift_pct.value_or(std::nan("")))
            << " %, loop closures " << loops << ", " << json(t.evaluated_length_m)
            << " m evaluated -> " << out << "\n";
}

/// A fleet's folder: each vehicle as a drive folder, then the merge; prints the fleet's figures.
void evaluateFleet(const std::string& drive, const std::string& out, const evaluate::Config& cfg,
                   const explore::Config& explore, bool keep_vehicles) {
  const evaluate::FleetResult r = evaluateFleetFolder(
      drive, out, cfg, keep_vehicles, [&cfg, &explore](const fs::path& d, const fs::path& o) {
        evaluateDriveFolder(d.string(), o.string(), cfg, explore);
      });
  for (const auto& v : r.vehicles)
    std::cout << v.id << ": ATE rmse " << v.own_ate_rmse_m << " m alone, " << v.common_ate_after_m
              << " m merged (one alignment)\n";
  std::cout << "fleet: " << r.closures.size() << " inter-vehicle closures, ATE rmse "
            << r.common_ate_before_m << " m before the merge, " << r.common_ate_after_m
            << " m after; completeness " << r.completeness_pct << " % -> " << out << "\n";
}

}  // namespace

void registerEvaluate(CLI::App& app, Context& ctx) {
  struct Opts {
    std::string drive, kitti, sensor = "paper", out;
    bool keep_vehicles = false;
    double segment_m = -1.0;
    int scan_stride = 0;
    double from_s = -1.0, to_s = -1.0;
    bool no_loop_closure = false;
  };
  auto o = std::make_shared<Opts>();
  auto* sub = app.add_subcommand(
      "evaluate",
      "Run LiDAR SLAM on a drive or a KITTI sequence and measure the error (paper 3.3)");
  auto* drive = sub->add_option("--drive", o->drive, "drive folder written by `slamroute drive`");
  auto* kitti = sub->add_option("--kitti", o->kitti,
                                "KITTI odometry sequence folder (velodyne/*.bin, times.txt; "
                                "optional poses.txt + calib.txt as ground truth)");
  drive->excludes(kitti);
  sub->add_option("--sensor", o->sensor,
                  "LiDAR of a --kitti sequence (rings come from the points' elevation)")
      ->check(CLI::IsMember({"paper", "vlp16", "hdl32"}))
      ->needs(kitti);
  sub->add_option("--out", o->out, "output folder (estimate.tum, metrics.json, map.pcd, plots)")
      ->required();
  sub->add_option("--segment", o->segment_m, "extra RPE segment length [m] (default: config)");
  sub->add_flag("--no-loop-closure", o->no_loop_closure, "disable loop closure");
  sub->add_flag("--keep-vehicles", o->keep_vehicles,
                "fleet: keep the vehicles' evaluations already in OUT/vehicle_K (merge only)");
  sub->add_option("--scan-stride", o->scan_stride,
                  "use every n-th scan (default: evaluate.input.scan_stride)")
      ->check(CLI::PositiveNumber);
  sub->add_option("--from", o->from_s, "evaluate only from this drive time on [s] (default: start)")
      ->check(CLI::NonNegativeNumber);
  sub->add_option("--to", o->to_s, "evaluate only up to this drive time [s] (default: end)")
      ->check(CLI::PositiveNumber);
  sub->callback([&ctx, o] {
    ctx.load();
    evaluate::Config cfg = ctx.cfg.evaluate;
    if (o->segment_m > 0) cfg.metrics.rpe_segment_m = o->segment_m;
    if (o->no_loop_closure) cfg.loop.enabled = false;
    if (o->scan_stride > 0) cfg.input.scan_stride = o->scan_stride;
    if (o->from_s >= 0) cfg.input.start_s = o->from_s;
    if (o->to_s > 0) cfg.input.end_s = o->to_s;
    if (cfg.input.end_s > 0 && cfg.input.end_s <= cfg.input.start_s)
      throw std::invalid_argument("--to must be later than --from");
    if (o->drive.empty() == o->kitti.empty())
      throw std::invalid_argument("evaluate needs --drive DIR or --kitti SEQ_DIR");
    if (!o->drive.empty() && FleetDriveInfo::isFleetFolder(o->drive)) {
      evaluateFleet(o->drive, o->out, cfg, ctx.cfg.explore, o->keep_vehicles);
      return;
    }
    const evaluate::EvaluationResult r =
        o->drive.empty() ? evaluateKittiSequence(o->kitti, o->sensor, o->out, cfg)
                         : evaluateDriveFolder(o->drive, o->out, cfg, ctx.cfg.explore);
    printSummary(r, o->out);
  });
}

}  // namespace slamroute::cli
