// mergeFleet: keyframes, inter-vehicle closures, one pose graph, then the fleet's metrics.
#include <filesystem>
#include <stdexcept>

#include "FleetInternal.hpp"
#include "FleetMap.hpp"
#include "slamroute/core/DriveFolder.hpp"
#include "slamroute/core/Log.hpp"

namespace slamroute::evaluate {
namespace {

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("fleet merge: " + what);
}

/// The merged map's accuracy as built and under the fleet's one alignment (as a single drive's
/// map is measured, MapOutput.hpp).
void measureMergedMap(const Mesh& mesh, const Config& cfg, FleetResult& r) {
  const double max_m = cfg.metrics.map_accuracy_max_m;
  Eigen::AlignedBox3f bounds;
  for (const auto& p : r.map) bounds.extend(p);
  MapAccuracyMeter built(mesh, max_m, bounds);
  built.add(r.map);
  const Cloud aligned = transformed(r.map, r.T_gt_est);
  MapAccuracyMeter meter(mesh, max_m, transformedBox(bounds, r.T_gt_est));
  meter.add(aligned, &r.map_aligned_dist_m);
  r.map_accuracy = built.result();
  r.map_aligned_accuracy = meter.result();
  r.map_accuracy_max_m = max_m;
}

/// Completeness per vehicle and merged, map accuracy of the merged map.
void measureMaps(const std::vector<FleetVehicleInput>& vehicles, const Config& cfg,
                 const FleetMergeOptions& opt, FleetResult& r) {
  std::vector<Trajectory> gts;
  for (const auto& v : vehicles) gts.push_back(v.ground_truth);
  const std::filesystem::path mesh_path = vehicles[0].drive_dir / drive_files::kWorldMesh;
  if (!std::filesystem::exists(mesh_path)) {
    logWarn("fleet merge: no " + mesh_path.string() + ": no completeness or map accuracy");
    return;
  }
  const Mesh mesh = readPly(mesh_path);
  const Cloud facades = streetFacades(mesh, gts, opt);
  r.facade_samples = static_cast<int>(facades.size());
  for (std::size_t v = 0; v < vehicles.size(); ++v) {
    const Cloud own =
        vehicleMap(vehicles[v], r.vehicles[v].merged, opt.map_scan_stride, cfg.output.map_voxel_m);
    r.vehicles[v].completeness_pct = coveredPct(facades, own, opt.covered_m);
    r.map.insert(r.map.end(), own.begin(), own.end());
  }
  r.map = voxelFilter(r.map, cfg.output.map_voxel_m);
  r.map_points = r.map.size();
  r.completeness_pct = coveredPct(facades, r.map, opt.covered_m);
  measureMergedMap(mesh, cfg, r);
}

void measureTrajectories(const std::vector<FleetVehicleInput>& vehicles, const Config& cfg,
                         FleetResult& r) {
  std::vector<Trajectory> own, merged, gts;
  for (std::size_t v = 0; v < vehicles.size(); ++v) {
    own.push_back(vehicles[v].estimate);
    merged.push_back(r.vehicles[v].merged);
    gts.push_back(vehicles[v].ground_truth);
    r.vehicles[v].own_ate_rmse_m =
        commonAteRmse({own.back()}, {gts.back()}, cfg.metrics.assoc_max_dt_s).front();
  }
  const std::vector<double> before = commonAteRmse(own, gts, cfg.metrics.assoc_max_dt_s);
  const std::vector<double> after =
      commonAteRmse(merged, gts, cfg.metrics.assoc_max_dt_s, &r.T_gt_est);
  for (std::size_t v = 0; v < vehicles.size(); ++v) {
    r.vehicles[v].common_ate_before_m = before[v];
    r.vehicles[v].common_ate_after_m = after[v];
  }
  r.common_ate_before_m = before.back();
  r.common_ate_after_m = after.back();
}

}  // namespace

void FleetMergeOptions::validate() const {
  require(keyframe_spacing_m > 0.0, "keyframe_spacing_m must be > 0");
  require(target_keyframes_each_side >= 0, "target_keyframes_each_side must be >= 0");
  require(gate_m > 0.0, "gate_m must be > 0");
  require(consistency_m > 0.0 && consistency_per_m >= 0.0 && consistency_window_m > 0.0 &&
              min_pair_closures >= 1,
          "consistency_m, consistency_window_m > 0, consistency_per_m >= 0 and "
          "min_pair_closures >= 1 needed");
  require(start_sigma_m > 0.0 && start_sigma_rad > 0.0, "start sigmas must be > 0");
  require(map_scan_stride >= 1, "map_scan_stride must be >= 1");
  require(facade_street_m > 0.0 && facade_sample_m > 0.0 && covered_m > 0.0,
          "facade_street_m, facade_sample_m and covered_m must be > 0");
}

FleetResult mergeFleet(const std::vector<FleetVehicleInput>& vehicles, const Config& cfg,
                       const FleetMergeOptions& opt) {
  opt.validate();
  require(!vehicles.empty(), "no vehicles");
  std::vector<std::vector<FleetKeyframe>> kfs;
  for (const auto& v : vehicles) {
    require(v.scans != nullptr, "vehicle " + v.id + " has no scans");
    kfs.push_back(fleetKeyframes(v.estimate, *v.scans, opt.keyframe_spacing_m));
  }
  FleetResult r;
  const std::vector<FleetClosure> verified =
      findFleetClosures(vehicles, kfs, cfg, opt, &r.candidates);
  r.closures = consistentClosures(verified, kfs, opt);
  r.inconsistent = static_cast<int>(verified.size() - r.closures.size());
  logInfo("fleet merge: " + std::to_string(r.closures.size()) + " inter-vehicle closures (" +
          std::to_string(r.candidates) + " candidates, " + std::to_string(verified.size()) +
          " verified, " + std::to_string(r.inconsistent) + " inconsistent dropped)");
  const std::vector<Trajectory> merged =
      mergeFleetTrajectories(vehicles, kfs, r.closures, cfg, opt);
  for (std::size_t v = 0; v < vehicles.size(); ++v) {
    FleetVehicleResult vr;
    vr.id = vehicles[v].id;
    vr.merged = merged[v];
    vr.keyframes = static_cast<int>(kfs[v].size());
    r.vehicles.push_back(std::move(vr));
  }
  measureTrajectories(vehicles, cfg, r);
  measureMaps(vehicles, cfg, opt, r);
  return r;
}

}  // namespace slamroute::evaluate
