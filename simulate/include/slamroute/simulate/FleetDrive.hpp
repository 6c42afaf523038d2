#pragma once
// `slamroute drive` of a fleet's route.json (core FleetRoute.hpp): every vehicle drives its route
// in ONE SUMO session among the same background traffic (and sees the other mapping vehicles as
// traffic); DIR/vehicle_K/ is vehicle K's drive folder, exactly as a single drive writes it
// (Drive.hpp), and DIR/fleet.json (core FleetDrive.hpp) names them. The world, its seed and the
// sensor are shared; each vehicle's wheel odometry and gyro have their own noise. All or
// nothing: a failed drive leaves no folder.
#include <filesystem>
#include <vector>

#include "slamroute/core/FleetDrive.hpp"
#include "slamroute/simulate/Drive.hpp"

namespace slamroute::simulate {

struct FleetDriveResult {
  std::filesystem::path out_dir;
  FleetDriveInfo info;
  std::vector<DriveResult> vehicles;  ///< in fleet order; out_dir is each vehicle's folder
  double wall_seconds = 0.0;
};

/// The seed of vehicle `index`'s odometry noise.
std::uint64_t fleetOdometrySeed(std::uint64_t seed, std::size_t index);

/// Runs the fleet's drive: opts.route_file is a fleet route.json.
FleetDriveResult runFleetDrive(const DriveOptions& opts, const Config& cfg);

}  // namespace slamroute::simulate
