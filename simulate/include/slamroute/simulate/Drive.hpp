#pragma once
// `slamroute drive`: the mapping vehicle ("mapper") follows a SUMO edge sequence among
// background traffic; the drive folder (core DriveFolder.hpp) receives
//   groundtruth.tum   sensor poses, TUM, record_hz (10 Hz): the 2D path and heading from SUMO
//                     (the vehicle's front reference point), the body standing on the world's
//                     road surface on its suspension (VehicleBody.hpp: pitch, roll, heave), the
//                     lidar mount height above the road on the body
//   pose_edges.csv    index,t,sumo_edge,lane_pos_m — the route edge each pose belongs to; in a
//                     junction (SUMO internal lane) the edge just left, with lane_pos_m = that
//                     edge's length + the distance into the junction
//   sensor.yaml       the lidar section (preset, resolved spec, noise)
//   world.yaml        net (absolute path), seed, world section
//   world.ply         the static world mesh
//   traffic.csv       other vehicles within range per pose (Traffic.hpp)
//   odometry.csv      wheel speed + gyro yaw rate + IMU roll / pitch (core Odometry.hpp)
//   odometry.yaml     their noise figures (core OdometrySpec.hpp), from DriveConfig
//   drive.json        route, length driven, duration, teleports (always 0), frames
//   scans/            only with save_scans: NNNNNN.bin (KITTI) + times.txt, and NNNNNN.time
//                     (each point's firing time) when the LiDAR models motion distortion
// Everything is written to a temporary folder beside DIR and renamed into place at the end,
// so a failed drive leaves nothing behind. A teleported, rerouted or unfinished mapper is an
// error (std::runtime_error), never a silently wrong trajectory.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "slamroute/core/Odometry.hpp"
#include "slamroute/core/Scan.hpp"
#include "slamroute/core/Trajectory.hpp"
#include "slamroute/simulate/Config.hpp"

namespace slamroute {
struct SumoNet;
}

namespace slamroute::simulate {

struct DriveOptions {
  std::filesystem::path net;
  std::filesystem::path
      route_file;  ///< route.json (planner), a JSON list of edges, or {"sumo_edges":[…]}
  std::filesystem::path out_dir;
  bool save_scans = false;       ///< write KITTI scans (else regenerated on demand)
  bool write_world_mesh = true;  ///< write world.ply
  /// Join consecutive edges SUMO does not connect with the shortest legal detour (a route
  /// planned on a trace-built graph can contain such turns); false: reject the route instead.
  bool join_forbidden_turns = true;
  std::uint64_t seed = 42;
};

struct PoseEdge {
  std::string sumo_edge;
  double lane_pos_m = 0.0;
};

struct DriveResult {
  std::filesystem::path out_dir;
  std::vector<std::string> route;    ///< SUMO edges driven
  Trajectory groundtruth;            ///< sensor poses T_world_sensor
  std::vector<PoseEdge> pose_edges;  ///< one per pose
  double route_length_m = 0.0;       ///< sum of the route's edge lengths
  double driven_m = 0.0;             ///< path length of the recorded positions
  double depart_s = 0.0, arrive_s = 0.0;
  int teleports = 0;
  std::size_t traffic_boxes = 0;  ///< rows of traffic.csv
  double wall_seconds = 0.0;
};

/// world.yaml of a drive folder: what regenerates the world (and, with sensor.yaml, the scans).
struct DriveWorldFile {
  std::string net;          ///< absolute path of the SUMO net
  std::uint64_t seed = 42;  ///< seed of the world and the sensor noise
  WorldConfig world;
};
template <class V>
void visitFields(V& v, DriveWorldFile& c) {
  v.field("net", c.net, "SUMO net (absolute path)");
  v.field("seed", c.seed, "seed of the world and the sensor noise");
  v.section("world", c.world);
}
/// Reads DIR/world.yaml. Throws std::runtime_error naming the file.
DriveWorldFile readDriveWorldFile(const std::filesystem::path& drive_dir);

/// Checks a route before SUMO starts: not empty, every edge in the net and open to passenger
/// cars, and (check_turns) every consecutive pair a turn SUMO allows (a <connection>). Throws
/// std::invalid_argument "WHERE: …" naming the first offending edge and its position.
void validateRoute(const SumoNet& net, const std::vector<std::string>& edges,
                   const std::string& where, bool check_turns = true);

/// The edge sequence a drive follows: validated as above; with `join_forbidden_turns` each
/// consecutive pair SUMO does not connect is joined by the shortest legal detour (a warning
/// says how many and how long). Throws std::invalid_argument "WHERE: …" when an edge is bad or
/// no legal way joins a pair.
std::vector<std::string> drivableRoute(const SumoNet& net, const std::vector<std::string>& edges,
                                       const std::string& where, bool join_forbidden_turns);

/// Quick look at map crispness: the scans stacked with their poses (point in world =
/// T_world_sensor * point), drawn top-down, every pixel coloured by the highest point in it
/// (blue low .. red high, scaled to [z_min, z_max]; black = empty). Uses every `stride`-th scan.
/// Written atomically. Returns the number of points drawn.
struct MapPngOptions {
  double metres_per_pixel = 0.2;
  std::size_t stride = 1;
  double z_min = -1.0, z_max = 10.0;  ///< colour range [m]
};
std::size_t renderStackedScansPng(const ScanSource& scans, const Trajectory& poses,
                                  const std::filesystem::path& png, const MapPngOptions& o = {});

/// The wheel odometry + gyro a survey car records, from the ground-truth sensor poses: forward
/// speed and yaw rate per pose interval, with a per-drive speed scale error and gyro bias and
/// white noise per sample (DriveConfig odometry_* / gyro_*), seeded. Deterministic.
WheelOdometry simulateOdometry(const Trajectory& groundtruth, const DriveConfig& cfg,
                               std::uint64_t seed);

/// Runs the drive (reads the net and the route, validates, simulates, writes out_dir).
DriveResult runDrive(const DriveOptions& opts, const Config& cfg);

}  // namespace slamroute::simulate
