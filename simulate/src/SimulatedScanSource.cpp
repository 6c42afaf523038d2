#include "slamroute/simulate/SimulatedScanSource.hpp"

#include <yaml-cpp/yaml.h>

#include <stdexcept>

#include "slamroute/core/ConfigIO.hpp"
#include "slamroute/core/DriveFolder.hpp"
#include "slamroute/core/SumoNet.hpp"
#include "slamroute/simulate/Drive.hpp"

namespace slamroute::simulate {

namespace fs = std::filesystem;

struct Parts {
  Trajectory gt;
  TrafficFrames traffic;
  DriveWorldFile wf;
  LidarConfig lidar;
};

namespace {
Parts readParts(const fs::path& dir) {
  if (!fs::is_directory(dir))
    throw std::runtime_error("drive folder " + dir.string() + " does not exist");
  Parts p;
  p.gt = readTum(dir / drive_files::kGroundTruth);
  if (p.gt.empty())
    throw std::runtime_error((dir / drive_files::kGroundTruth).string() + ": no poses");
  p.wf = readDriveWorldFile(dir);
  const fs::path sensor = dir / drive_files::kSensor;
  if (!fs::exists(sensor)) throw std::runtime_error(sensor.string() + " is missing");
  try {
    config::loadYaml(YAML::LoadFile(sensor.string()), p.lidar, sensor.string());
  } catch (const YAML::Exception& e) {
    throw std::runtime_error(sensor.string() + ": " + e.what());
  }
  const fs::path traffic = dir / kTrafficFile;
  p.traffic =
      fs::exists(traffic) ? readTrafficCsv(traffic, p.gt.size()) : TrafficFrames(p.gt.size());
  return p;
}

World buildWorld(const Parts& p) {
  if (p.wf.net.empty()) throw std::runtime_error("world.yaml names no net");
  return World::build(SumoNet::read(p.wf.net), p.wf.world, p.wf.seed);
}
}  // namespace

SimulatedScanSource::SimulatedScanSource(const fs::path& drive_dir)
    : SimulatedScanSource(drive_dir, readParts(drive_dir)) {}

SimulatedScanSource::SimulatedScanSource(const fs::path& dir, Parts&& p)
    : dir_(dir),
      groundtruth_(std::move(p.gt)),
      traffic_(std::move(p.traffic)),
      world_(buildWorld(p)),
      lidar_(p.lidar, p.wf.seed) {}

Scan SimulatedScanSource::scan(std::size_t i) const {
  if (i >= groundtruth_.size())
    throw std::out_of_range("scan " + std::to_string(i) + " of drive " + dir_.string() + " (has " +
                            std::to_string(groundtruth_.size()) + ")");
  static const std::vector<VehicleBox> none;
  return lidar_.scan(world_, groundtruth_[i].T_world_body,
                     sweepEndPose(groundtruth_, i, lidar_.config().sweep_period_s),
                     i < traffic_.size() ? traffic_[i] : none, i, groundtruth_[i].t);
}

}  // namespace slamroute::simulate
