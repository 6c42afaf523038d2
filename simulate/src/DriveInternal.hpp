#pragma once
// Internals of runDrive shared by Drive.cpp (simulation) and DriveOutput.cpp (files).
#include <string>
#include <vector>

#include "slamroute/core/Scan.hpp"
#include "slamroute/simulate/Drive.hpp"
#include "slamroute/simulate/Traffic.hpp"

namespace slamroute::simulate {

class World;

/// What the simulation produced, before anything is written.
struct DriveRecord {
  Trajectory groundtruth;            ///< T_world_sensor per recorded step
  std::vector<PoseEdge> pose_edges;  ///< one per pose
  TrafficFrames traffic;             ///< one per pose
  double route_length_m = 0.0;
  double depart_s = 0.0, arrive_s = 0.0;
  int background_vehicles = 0;
};

/// One mapping vehicle: its SUMO id and its (validated) edges.
struct MapperToDrive {
  std::string id;
  std::vector<std::string> edges;
};

/// Runs SUMO: one session, every mapper on its edges, all departing at 0 (SUMO inserts them as
/// space allows), background traffic; one record per mapper, in order.
std::vector<DriveRecord> recordMappers(const SumoNet& net,
                                       const std::vector<MapperToDrive>& mappers, const Config& cfg,
                                       const LidarSpec& spec, std::uint64_t seed);

/// Runs SUMO: one session, the mapper on `edges` (already validated), background traffic.
DriveRecord recordDrive(const SumoNet& net, const std::vector<std::string>& edges,
                        const Config& cfg, const LidarSpec& spec, std::uint64_t seed);

/// Simulates the LiDAR along the ground truth (static world + traffic boxes) and writes KITTI
/// scans DIR/NNNNNN.bin + DIR/times.txt.
void writeDriveScans(const std::filesystem::path& dir, const World& world, const Trajectory& gt,
                     const TrafficFrames& traffic, const LidarConfig& lidar, std::uint64_t seed);

/// Writes every file of the drive folder into `dir` (the staging folder). The odometry noise
/// is drawn from `odometry_seed` (each vehicle of a fleet has its own wheels and gyro).
DriveResult writeDriveFolder(const std::filesystem::path& dir, const SumoNet& net,
                             const std::vector<std::string>& edges, const DriveRecord& rec,
                             const World& world, const Config& cfg, const LidarSpec& spec,
                             const DriveOptions& opts, std::uint64_t odometry_seed);

}  // namespace slamroute::simulate
