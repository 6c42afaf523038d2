#pragma once
// ScanSource backed by the simulator: regenerates scan i of a drive on demand from the drive
// folder (core DriveFolder.hpp) — groundtruth.tum (sensor poses T_world_sensor), sensor.yaml
// (LidarConfig with the resolved spec), world.yaml (net path, seed, world config) and, when
// present, traffic.csv (vehicle boxes per pose). Scan i is Lidar::scan(world, pose i,
// sweepEndPose(i), boxes i, index i, t_i) with the drive's seed: bitwise what
// `drive --save-scans` writes. The evaluator
// only sees ScanSource; Embree stays inside this module.
#include <filesystem>

#include "slamroute/core/Scan.hpp"
#include "slamroute/core/Trajectory.hpp"
#include "slamroute/simulate/Lidar.hpp"
#include "slamroute/simulate/Traffic.hpp"
#include "slamroute/simulate/World.hpp"

namespace slamroute::simulate {

class SimulatedScanSource : public ScanSource {
 public:
  /// Reads the drive folder and builds the world (seconds for a city). Throws
  /// std::runtime_error / std::invalid_argument naming the missing or bad file.
  explicit SimulatedScanSource(const std::filesystem::path& drive_dir);

  std::size_t size() const override { return groundtruth_.size(); }
  double time(std::size_t i) const override { return groundtruth_.at(i).t; }
  /// Thread-safe (const; may be called concurrently). Throws std::out_of_range naming i.
  Scan scan(std::size_t i) const override;
  LidarSpec spec() const override { return lidar_.spec(); }

  const World& world() const { return world_; }
  const Trajectory& groundtruth() const { return groundtruth_; }
  const TrafficFrames& traffic() const { return traffic_; }

 private:
  SimulatedScanSource(const std::filesystem::path& dir, struct Parts&& parts);
  std::filesystem::path dir_;
  Trajectory groundtruth_;
  TrafficFrames traffic_;
  World world_;
  Lidar lidar_;
};

}  // namespace slamroute::simulate
