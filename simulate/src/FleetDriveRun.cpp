// runFleetDrive: K mapping vehicles in one SUMO session, one drive folder each plus fleet.json.
#include <chrono>

#include "DriveInternal.hpp"
#include "LidarNoise.hpp"
#include "slamroute/core/FleetRoute.hpp"
#include "slamroute/core/Log.hpp"
#include "slamroute/core/StagingDir.hpp"
#include "slamroute/core/SumoNet.hpp"
#include "slamroute/simulate/FleetDrive.hpp"
#include "slamroute/simulate/VehicleBody.hpp"
#include "slamroute/simulate/World.hpp"

namespace slamroute::simulate {
namespace fs = std::filesystem;
namespace {

std::vector<MapperToDrive> fleetMappers(const SumoNet& net, const FleetRoute& fleet,
                                        const DriveOptions& opts) {
  std::vector<MapperToDrive> mappers;
  for (std::size_t k = 0; k < fleet.vehicles.size(); ++k) {
    const std::string where = opts.route_file.string() + " (vehicle " + std::to_string(k) + ")";
    mappers.push_back({FleetRoute::vehicleId(k), drivableRoute(net, fleet.vehicles[k].sumo_edges,
                                                               where, opts.join_forbidden_turns)});
  }
  return mappers;
}

FleetDriveVehicle fleetEntry(const DriveResult& r, const std::string& id, std::size_t k) {
  FleetDriveVehicle v;
  v.id = id;
  v.folder = FleetDriveInfo::folderName(k);
  v.route_length_m = r.route_length_m;
  v.driven_m = r.driven_m;
  v.depart_s = r.depart_s;
  v.arrive_s = r.arrive_s;
  v.frames = r.groundtruth.size();
  return v;
}

}  // namespace

std::uint64_t fleetOdometrySeed(std::uint64_t seed, std::size_t index) {
  return detail::splitmix(seed ^ detail::splitmix(0xf1ee7ULL + index));
}

FleetDriveResult runFleetDrive(const DriveOptions& opts, const Config& cfg) {
  const auto wall0 = std::chrono::steady_clock::now();
  const SumoNet net = SumoNet::read(opts.net);
  const FleetRoute fleet = FleetRoute::readJson(opts.route_file);
  const std::vector<MapperToDrive> mappers = fleetMappers(net, fleet, opts);
  const LidarSpec spec = resolveLidarSpec(cfg.lidar);
  StagingDir staging(opts.out_dir, kFleetDriveInfo);

  logInfo("drive: a fleet of " + std::to_string(mappers.size()) + " vehicles on " +
          opts.net.string());
  validate(cfg.drive.body);
  std::vector<DriveRecord> records = recordMappers(net, mappers, cfg, spec, opts.seed);
  logInfo("drive: building the 3D world");
  const World world = World::build(net, cfg.world, opts.seed);
  FleetDriveResult res;
  res.info.net = fs::absolute(net.source).lexically_normal().string();
  res.info.seed = opts.seed;
  for (std::size_t k = 0; k < mappers.size(); ++k) {
    DriveRecord& rec = records[k];
    rec.groundtruth =
        vehicleSensorPoses(rec.groundtruth, world, cfg.drive.body, spec.mount_height_m);
    const fs::path dir = staging.path() / FleetDriveInfo::folderName(k);
    fs::create_directories(dir);
    res.vehicles.push_back(writeDriveFolder(dir, net, mappers[k].edges, rec, world, cfg, spec, opts,
                                            fleetOdometrySeed(opts.seed, k)));
    res.info.vehicles.push_back(fleetEntry(res.vehicles.back(), mappers[k].id, k));
  }
  res.info.write(staging.path());
  staging.commit();
  res.out_dir = staging.target();
  for (std::size_t k = 0; k < res.vehicles.size(); ++k)
    res.vehicles[k].out_dir = res.out_dir / FleetDriveInfo::folderName(k);
  res.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  return res;
}

}  // namespace slamroute::simulate
