// `slamroute evaluate --drive DIR --out DIR2`: paper §3.3 — LeGO-LOAM-style SLAM on a drive's
// scans, then ATE/RPE/per-edge/map metrics against the drive's ground truth.
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>

#include "Commands.hpp"
#include "slamroute/core/DriveFolder.hpp"
#include "slamroute/core/Log.hpp"
#include "slamroute/evaluate/DriveChecks.hpp"
#include "slamroute/evaluate/Evaluate.hpp"
#include "slamroute/core/SumoNet.hpp"
#include "slamroute/simulate/Drive.hpp"
#include "slamroute/simulate/SimulatedScanSource.hpp"
#include "slamroute/simulate/World.hpp"

namespace slamroute::cli {

void registerEvaluate(CLI::App& app, Context& ctx) {
  struct Opts {
    std::string drive, out;
    double segment_m = -1.0;
    int scan_stride = 0;
    double from_s = -1.0, to_s = -1.0;
    bool no_loop_closure = false;
  };
  auto o = std::make_shared<Opts>();
  auto* sub = app.add_subcommand("evaluate", "Run LiDAR SLAM on a drive and measure the error (paper 3.3)");
  sub->add_option("--drive", o->drive, "drive folder written by `slamroute drive`")->required();
  sub->add_option("--out", o->out, "output folder (estimate.tum, metrics.json, map.pcd, plots)")->required();
  sub->add_option("--segment", o->segment_m, "extra RPE segment length [m] (default: config)");
  sub->add_flag("--no-loop-closure", o->no_loop_closure, "disable loop closure");
  sub->add_option("--scan-stride", o->scan_stride, "use every n-th scan (default: evaluate.scan_stride)")
      ->check(CLI::PositiveNumber);
  sub->add_option("--from", o->from_s, "evaluate only from this drive time on [s] (default: start)")
      ->check(CLI::NonNegativeNumber);
  sub->add_option("--to", o->to_s, "evaluate only up to this drive time [s] (default: end)")
      ->check(CLI::PositiveNumber);
  sub->callback([&ctx, o] {
    ctx.load();
    namespace fs = std::filesystem;
    evaluate::Config cfg = ctx.cfg.evaluate;
    if (o->segment_m > 0) cfg.rpe_segment_m = o->segment_m;
    if (o->no_loop_closure) cfg.loop_closure = false;
    if (o->scan_stride > 0) cfg.scan_stride = o->scan_stride;
    if (o->from_s >= 0) cfg.start_s = o->from_s;
    if (o->to_s > 0) cfg.end_s = o->to_s;
    if (cfg.end_s > 0 && cfg.end_s <= cfg.start_s)
      throw std::invalid_argument("--to must be later than --from");
    if (!(cfg.map_tile_m > 0))  // checked before the scans are read or made
      throw std::invalid_argument((ctx.config_file.empty() ? std::string("config") : ctx.config_file) +
                                  ": evaluate.map_tile_m must be positive");
    const fs::path drive(o->drive);
    if (!fs::is_directory(drive)) throw std::invalid_argument(o->drive + ": not a drive folder");
    if (!fs::exists(drive / drive_files::kGroundTruth))
      throw std::invalid_argument(o->drive + ": no " + drive_files::kGroundTruth + " (not a drive folder?)");
    const LidarSpec spec = evaluate::readSensorSpec(drive / drive_files::kSensor);
    std::unique_ptr<ScanSource> source;
    if (fs::is_directory(drive / drive_files::kScanDir)) {
      source = std::make_unique<KittiScanSource>(drive / drive_files::kScanDir, spec);
    } else {
      logInfo("evaluate: no scans/ in the drive, regenerating scans with the simulator");
      source = std::make_unique<simulate::SimulatedScanSource>(drive);
    }
    evaluate::checkDriveFiles(drive, *source);
    logInfo("evaluate: " + std::to_string(source->size()) + " scans from " + o->drive);
    // Simulated drives: label each street with the kind the world lines it with (rich / wall /
    // open), so metrics.json shows the drift per kind of street.
    std::map<std::string, std::string> kinds;
    if (fs::exists(drive / drive_files::kWorld)) {
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
    }
    const nlohmann::json j = evaluate::evaluateDrive(drive, *source, o->out, cfg, kinds);
    std::cout << "ATE rmse " << j["ate_rmse_m"] << " m, RPE " << j["rpe_trans_pct"] << " %, loop closures "
              << j["loop_closures"] << ", " << j["evaluated_length_m"] << " m evaluated -> " << o->out << "\n";
  });
}

}  // namespace slamroute::cli
