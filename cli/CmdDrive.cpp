// `slamroute drive --net NET --route ROUTE.json --out DIR [--save-scans] [--sensor P]`:
// the mapping vehicle drives the route in SUMO among background traffic (simulate/Drive.hpp).
#include <cstdio>
#include <iostream>

#include "Commands.hpp"
#include "slamroute/core/DriveFolder.hpp"
#include "slamroute/core/FleetRoute.hpp"
#include "slamroute/simulate/Drive.hpp"
#include "slamroute/simulate/FleetDrive.hpp"
#include "slamroute/simulate/SimulatedScanSource.hpp"

namespace slamroute::cli {

namespace {

struct DriveOpts {
  std::string net, route, out, sensor, map_png;
  std::size_t map_stride = 1;
  double map_res = 0.2;
  bool save_scans = false, no_mesh = false, strict_turns = false;
  double traffic = -1.0;
};

void addDriveOptions(CLI::App* sub, DriveOpts& o) {
  sub->add_option("--net", o.net, "SUMO network (.net.xml); default: the shipped default city");
  sub->add_option("--route", o.route,
                  "route.json from `plan`, a JSON list of SUMO edges, or {\"sumo_edges\":[...]}")
      ->required();
  sub->add_option("--out", o.out, "drive folder to write")->required();
  sub->add_flag("--save-scans", o.save_scans,
                "write KITTI scans DIR/scans/NNNNNN.bin (otherwise regenerated on demand)");
  sub->add_option("--sensor", o.sensor, "LiDAR preset (overrides simulate.lidar.preset)")
      ->check(CLI::IsMember({"paper", "vlp16", "hdl32"}));
  sub->add_option("--traffic", o.traffic,
                  "background vehicles per km of road (overrides simulate.drive.traffic_per_km)");
  sub->add_option("--map-png", o.map_png,
                  "also draw the scans stacked with the ground truth, top-down, to this PNG");
  sub->add_option("--map-stride", o.map_stride, "use every N-th scan for --map-png")
      ->check(CLI::PositiveNumber);
  sub->add_option("--map-resolution", o.map_res, "metres per pixel of --map-png")
      ->check(CLI::PositiveNumber);
  sub->add_flag("--no-mesh", o.no_mesh, "do not write world.ply");
  sub->add_flag("--strict-turns", o.strict_turns,
                "reject a route with a turn SUMO does not allow (default: join it by the shortest "
                "legal detour, with a warning)");
}

simulate::DriveOptions driveOptions(const Context& ctx, const DriveOpts& o) {
  simulate::DriveOptions d;
  d.net = o.net.empty() ? defaultNetPath() : o.net;
  d.route_file = o.route;
  d.out_dir = o.out;
  d.save_scans = o.save_scans;
  d.write_world_mesh = !o.no_mesh;
  d.join_forbidden_turns = !o.strict_turns;
  d.seed = ctx.cfg.seed;
  return d;
}

/// --map-png: the drive's scans (saved, or regenerated) stacked on the ground truth.
void drawStackedScans(const DriveOpts& o, const simulate::Config& cfg,
                      const simulate::DriveResult& r) {
  simulate::MapPngOptions mo;
  mo.stride = o.map_stride;
  mo.metres_per_pixel = o.map_res;
  std::size_t n = 0;
  if (o.save_scans) {
    const KittiScanSource src(r.out_dir / drive_files::kScanDir,
                              simulate::resolveLidarSpec(cfg.lidar));
    n = simulate::renderStackedScansPng(src, r.groundtruth, o.map_png, mo);
  } else {
    const simulate::SimulatedScanSource src(r.out_dir);
    n = simulate::renderStackedScansPng(src, src.groundtruth(), o.map_png, mo);
  }
  std::cout << "map: " << n << " points drawn to " << o.map_png << "\n";
}

std::string driveLine(const simulate::DriveResult& r) {
  char line[256];
  std::snprintf(
      line, sizeof line, "%zu edges, %.0f m driven in %.1f s simulated (%zu poses, %d teleports)",
      r.route.size(), r.driven_m, r.arrive_s - r.depart_s, r.groundtruth.size(), r.teleports);
  return line;
}

/// A fleet's route.json: every vehicle in one SUMO session, DIR/vehicle_K + DIR/fleet.json.
void driveFleet(const simulate::DriveOptions& d, const simulate::Config& cfg) {
  const simulate::FleetDriveResult r = simulate::runFleetDrive(d, cfg);
  for (std::size_t k = 0; k < r.vehicles.size(); ++k)
    std::cout << "drive: " << r.info.vehicles[k].id << ": " << driveLine(r.vehicles[k]) << "\n";
  char line[160];
  std::snprintf(line, sizeof line, "drive: fleet of %zu, makespan %.1f s simulated, %.1f s wall",
                r.vehicles.size(), r.info.makespanSeconds(), r.wall_seconds);
  std::cout << line << "\n"
            << "wrote " << r.out_dir.string() << "\n";
}

void runDriveCommand(Context& ctx, const DriveOpts& o) {
  ctx.load();
  simulate::Config cfg = ctx.cfg.simulate;
  if (!o.sensor.empty()) cfg.lidar.preset = o.sensor;
  if (o.traffic >= 0.0) cfg.drive.traffic_per_km = o.traffic;
  const simulate::DriveOptions d = driveOptions(ctx, o);
  if (FleetRoute::isFleetFile(d.route_file)) {
    if (!o.map_png.empty()) throw std::invalid_argument("--map-png: one vehicle only");
    return driveFleet(d, cfg);
  }
  const simulate::DriveResult r = simulate::runDrive(d, cfg);
  char wall[64];
  std::snprintf(wall, sizeof wall, ", %.1f s wall", r.wall_seconds);
  std::cout << "drive: " << driveLine(r) << wall << "\n"
            << "wrote " << r.out_dir.string() << "\n";
  if (!o.map_png.empty()) drawStackedScans(o, cfg, r);
}

}  // namespace

void registerDrive(CLI::App& app, Context& ctx) {
  auto o = std::make_shared<DriveOpts>();
  auto* sub = app.add_subcommand(
      "drive", "Drive a route in SUMO with traffic; record ground truth (and LiDAR scans)");
  addDriveOptions(sub, *o);
  sub->callback([&ctx, o] { runDriveCommand(ctx, *o); });
}

}  // namespace slamroute::cli
