// addMapCompleteness: estimate + scans -> occupancy grid -> completeness figures and picture.
#include "EvaluateCompleteness.hpp"

#include "slamroute/core/DriveFolder.hpp"
#include "slamroute/core/Log.hpp"
#include "slamroute/core/SumoNet.hpp"
#include "slamroute/core/Trajectory.hpp"
#include "slamroute/explore/MapCompleteness.hpp"
#include "slamroute/simulate/Drive.hpp"

namespace slamroute::cli {
namespace fs = std::filesystem;

void addMapCompleteness(const fs::path& drive, const ScanSource& scans, const fs::path& out,
                        const explore::Config& cfg, evaluate::EvaluationResult& r) {
  if (!fs::exists(drive / drive_files::kWorld)) return;
  const simulate::DriveWorldFile wf = simulate::readDriveWorldFile(drive);
  const RoadGraph g = RoadGraph::fromSumoNet(SumoNet::read(wf.net));
  const Trajectory estimate = readTum(out / "estimate.tum");
  const explore::OccupancyGrid grid =
      explore::occupancyFromScans(scans, estimate, g, cfg.grid, cfg.sensor.scan_spacing_m);
  const std::vector<bool> mask = explore::streetMask(grid, g, cfg.completeness_radius_m);
  const explore::MapCompleteness m = explore::mapCompleteness(grid, mask, cfg.gp);
  r.map_completeness = evaluate::MapCompletenessFigures{
      cfg.completeness_radius_m, static_cast<long long>(m.cells), m.unknown_share, m.frontier_share,
      m.mean_frontier_probability};
  explore::writeFrontierProbabilityPng(out / kFrontierPng, grid, mask, cfg.gp);
  evaluate::writeEvaluationJson(out / "metrics.json", r);
  logInfo(
      "evaluate: map completeness near the streets: " + std::to_string(100.0 * m.unknown_share) +
      " % unknown, " + std::to_string(100.0 * m.frontier_share) + " % frontier");
}

}  // namespace slamroute::cli
