// The evaluation of a fleet's drive folder (fleet.json).
#include "EvaluateFleet.hpp"

#include <memory>

#include "slamroute/core/DriveFolder.hpp"
#include "slamroute/core/FleetDrive.hpp"
#include "slamroute/core/Log.hpp"
#include "slamroute/evaluate/Evaluate.hpp"
#include "slamroute/simulate/SimulatedScanSource.hpp"

namespace slamroute::cli {
namespace fs = std::filesystem;

namespace {

std::unique_ptr<ScanSource> vehicleScans(const fs::path& drive) {
  if (fs::is_directory(drive / drive_files::kScanDir))
    return std::make_unique<KittiScanSource>(
        drive / drive_files::kScanDir, evaluate::readSensorSpec(drive / drive_files::kSensor));
  return std::make_unique<simulate::SimulatedScanSource>(drive);
}

}  // namespace

evaluate::FleetResult evaluateFleetFolder(const fs::path& drive, const fs::path& out,
                                          const evaluate::Config& cfg, bool keep_vehicles,
                                          const EvaluateOne& evaluate_one) {
  const FleetDriveInfo info = FleetDriveInfo::read(drive);
  std::vector<std::unique_ptr<ScanSource>> scans;
  std::vector<evaluate::FleetVehicleInput> inputs;
  std::vector<std::string> folders;
  for (const auto& v : info.vehicles) {
    const fs::path vdrive = drive / v.folder, vout = out / v.folder;
    if (keep_vehicles && fs::exists(vout / "metrics.json"))
      logInfo("evaluate: keeping " + vout.string());
    else
      evaluate_one(vdrive, vout);
    scans.push_back(vehicleScans(vdrive));
    inputs.push_back({v.id, vdrive, readTum(vout / "estimate.tum"),
                      readTum(vdrive / drive_files::kGroundTruth), scans.back().get()});
    folders.push_back(v.folder);
  }
  logInfo("evaluate: merging the maps of " + std::to_string(inputs.size()) + " vehicles");
  evaluate::FleetResult r = evaluate::mergeFleet(inputs, cfg, evaluate::FleetMergeOptions{});
  evaluate::writeFleetOutputs(out, r, folders);
  return r;
}

}  // namespace slamroute::cli
