#include "HtmlFleetDrives.hpp"

#include "slamroute/core/DriveFolder.hpp"
#include "slamroute/core/FleetDrive.hpp"
#include "slamroute/core/Trajectory.hpp"

namespace slamroute::cli {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

/// One vehicle's associated poses.
struct VehiclePairs {
  std::string id;
  std::vector<evaluate::PosePair> pairs;
};

/// Every vehicle's merged estimate associated with its ground truth; empty when one is missing.
std::vector<VehiclePairs> associatedVehicles(const fs::path& drive_dir, const fs::path& eval_dir) {
  if (!FleetDriveInfo::isFleetFolder(drive_dir)) return {};
  std::vector<VehiclePairs> out;
  for (const auto& v : FleetDriveInfo::read(drive_dir).vehicles) {
    const fs::path est = eval_dir / ("merged_" + v.folder + ".tum"),
                   gt = drive_dir / v.folder / drive_files::kGroundTruth;
    if (!fs::exists(est) || !fs::exists(gt)) return {};
    out.push_back({v.id, evaluate::associate(readTum(est), readTum(gt),
                                             evaluate::MetricsOptions{}.max_dt_s)});
  }
  return out;
}

/// Distance driven along the ground truth at each pair [m].
std::vector<double> distanceAlong(const std::vector<evaluate::PosePair>& pairs) {
  std::vector<double> d;
  for (std::size_t i = 0; i < pairs.size(); ++i)
    d.push_back(i == 0 ? 0.0
                       : d.back() +
                             (pairs[i].gt.translation() - pairs[i - 1].gt.translation()).norm());
  return d;
}

std::vector<double> errorsAfter(const std::vector<evaluate::PosePair>& pairs, const Pose3& T) {
  std::vector<double> err;
  for (const auto& p : pairs) err.push_back((T * p.est.translation() - p.gt.translation()).norm());
  return err;
}

}  // namespace

json fleetDriveLayers(const fs::path& drive_dir, const fs::path& eval_dir, const MapFrame& f) {
  const std::vector<VehiclePairs> vehicles = associatedVehicles(drive_dir, eval_dir);
  std::vector<evaluate::PosePair> all;
  for (const auto& v : vehicles) all.insert(all.end(), v.pairs.begin(), v.pairs.end());
  json out = json::array();
  if (all.empty()) return out;
  const Pose3 T = evaluate::alignUmeyama(all);
  for (const auto& v : vehicles)
    out.push_back(
        {{"id", v.id},
         {"drive", driveLayer(v.pairs, T, distanceAlong(v.pairs), errorsAfter(v.pairs, T), f)}});
  return out;
}

}  // namespace slamroute::cli
