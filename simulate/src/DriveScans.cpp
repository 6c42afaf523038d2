// writeDriveScans: KITTI scans of a drive (only with --save-scans). Scan i is Lidar::scan with
// index i and the drive's seed, sweeping from pose i to sweepEndPose(i) — exactly what
// SimulatedScanSource regenerates on demand. Point times go beside each .bin (NNNNNN.time).
#include <cstdio>
#include <sstream>

#include "DriveInternal.hpp"
#include "slamroute/core/AtomicFile.hpp"
#include "slamroute/core/Log.hpp"
#include "slamroute/simulate/Lidar.hpp"
#include "slamroute/simulate/World.hpp"

namespace slamroute::simulate {

void writeDriveScans(const std::filesystem::path& dir, const World& world, const Trajectory& gt,
                     const TrafficFrames& traffic, const LidarConfig& lidar_cfg,
                     std::uint64_t seed) {
  std::filesystem::create_directories(dir);
  const Lidar lidar(lidar_cfg, seed);
  constexpr std::size_t kBatch = 32;
  Progress progress("scans", gt.size());
  std::ostringstream times;
  times.precision(12);
  for (std::size_t first = 0; first < gt.size(); first += kBatch) {
    const std::size_t last = std::min(gt.size(), first + kBatch);
    std::vector<Pose3> poses, ends;
    std::vector<std::vector<VehicleBox>> boxes;
    std::vector<double> ts;
    for (std::size_t i = first; i < last; ++i) {
      poses.push_back(gt[i].T_world_body);
      ends.push_back(sweepEndPose(gt, i, lidar_cfg.sweep_period_s));
      boxes.push_back(i < traffic.size() ? traffic[i] : std::vector<VehicleBox>{});
      ts.push_back(gt[i].t);
    }
    const std::vector<Scan> scans = lidar.scanMany(world, poses, ends, boxes, first, ts);
    for (std::size_t k = 0; k < scans.size(); ++k) {
      char name[32];
      std::snprintf(name, sizeof name, "%06zu.bin", first + k);
      writeKittiScan(dir / name, scans[k]);
      times << ts[k] << "\n";
    }
    progress.update(last);
  }
  progress.finish();
  writeFileAtomic(dir / "times.txt", times.str());
}

}  // namespace slamroute::simulate
