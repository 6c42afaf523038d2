// writeDriveFolder: the files of a drive folder (see Drive.hpp), written into the staging folder.
#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>

#include "DriveInternal.hpp"
#include "slamroute/core/AtomicFile.hpp"
#include "slamroute/core/ConfigIO.hpp"
#include "slamroute/core/DriveFolder.hpp"
#include "slamroute/core/Log.hpp"
#include "slamroute/core/OdometrySpec.hpp"
#include "slamroute/core/SumoNet.hpp"
#include "slamroute/simulate/World.hpp"

namespace slamroute::simulate {
namespace fs = std::filesystem;
namespace {

std::string poseEdgesCsv(const DriveRecord& rec) {
  std::ostringstream os;
  os.precision(10);
  os << "index,t,sumo_edge,lane_pos_m\n";
  for (std::size_t i = 0; i < rec.pose_edges.size(); ++i) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.3f", rec.groundtruth[i].t);
    os << i << "," << buf << "," << rec.pose_edges[i].sumo_edge << ",";
    std::snprintf(buf, sizeof buf, "%.3f", rec.pose_edges[i].lane_pos_m);
    os << buf << "\n";
  }
  return os.str();
}

}  // namespace

DriveWorldFile readDriveWorldFile(const fs::path& drive_dir) {
  const fs::path path = drive_dir / drive_files::kWorld;
  const std::string text = readFile(path);
  DriveWorldFile wf;
  try {
    config::loadYaml(YAML::Load(text), wf, path.string());
  } catch (const YAML::Exception& e) {
    throw std::runtime_error(path.string() + ": not valid YAML (" + e.msg + ")");
  }
  if (wf.net.empty()) throw std::runtime_error(path.string() + ": no 'net'");
  return wf;
}

DriveResult writeDriveFolder(const fs::path& dir, const SumoNet& net,
                             const std::vector<std::string>& edges, const DriveRecord& rec,
                             const World& world, const Config& cfg, const LidarSpec& spec,
                             const DriveOptions& opts, std::uint64_t odometry_seed) {
  DriveResult res;
  res.route = edges;
  res.groundtruth = rec.groundtruth;
  res.pose_edges = rec.pose_edges;
  res.route_length_m = rec.route_length_m;
  res.driven_m = pathLength(rec.groundtruth);
  res.depart_s = rec.depart_s;
  res.arrive_s = rec.arrive_s;
  res.teleports = 0;  // a teleport of the mapper aborts the drive (recordDrive)

  writeTum(dir / drive_files::kGroundTruth, rec.groundtruth);
  writeFileAtomic(dir / drive_files::kPoseEdges, poseEdgesCsv(rec));
  writeOdometryCsv(dir / drive_files::kOdometry,
                   simulateOdometry(rec.groundtruth, cfg.drive, odometry_seed));
  OdometrySpec odo_spec;
  odo_spec.scale_sigma = cfg.drive.odometry_scale_sigma;
  odo_spec.speed_noise_mps = cfg.drive.odometry_speed_noise_mps;
  odo_spec.gyro_bias_sigma_deg_s = cfg.drive.gyro_bias_sigma_deg_s;
  odo_spec.gyro_noise_deg_s = cfg.drive.gyro_noise_deg_s;
  writeOdometrySpec(dir / drive_files::kOdometrySpec, odo_spec);

  std::vector<double> times;
  times.reserve(rec.groundtruth.size());
  for (const auto& p : rec.groundtruth) times.push_back(p.t);
  writeTrafficCsv(dir / kTrafficFile, rec.traffic, times);
  for (const auto& f : rec.traffic) res.traffic_boxes += f.size();

  // sensor.yaml: the lidar section with the spec resolved from the preset (re-resolving it gives
  // the same sensor).
  LidarConfig lidar = cfg.lidar;
  lidar.spec = spec;
  writeFileAtomic(dir / drive_files::kSensor, config::dumpYaml(lidar));
  DriveWorldFile wf;
  wf.net = fs::absolute(net.source).lexically_normal().string();
  wf.seed = opts.seed;
  wf.world = cfg.world;
  writeFileAtomic(dir / drive_files::kWorld, config::dumpYaml(wf));

  if (opts.write_world_mesh || opts.save_scans) {
    if (opts.write_world_mesh) world.writePly(dir / drive_files::kWorldMesh);
    if (opts.save_scans) {
      // Scans from the poses and boxes as written (rounded), so that SimulatedScanSource,
      // which reads the files, regenerates exactly these scans.
      const Trajectory gt = readTum(dir / drive_files::kGroundTruth);
      const TrafficFrames traffic = readTrafficCsv(dir / kTrafficFile, gt.size());
      writeDriveScans(dir / drive_files::kScanDir, world, gt, traffic, lidar, opts.seed);
    }
  }

  nlohmann::json j;
  j["net"] = wf.net;
  j["seed"] = opts.seed;
  j["route"] = edges;
  j["route_edges"] = edges.size();
  j["route_length_m"] = res.route_length_m;
  j["driven_m"] = res.driven_m;
  j["depart_s"] = res.depart_s;
  j["arrive_s"] = res.arrive_s;
  j["duration_s"] = res.arrive_s - res.depart_s;
  j["teleports"] = res.teleports;
  j["frames"] = rec.groundtruth.size();
  j["record_hz"] = cfg.drive.record_hz;
  j["sensor_preset"] = cfg.lidar.preset;
  j["channels"] = spec.channels;
  j["background_vehicles"] = rec.background_vehicles;
  j["traffic_boxes"] = res.traffic_boxes;
  j["scans_saved"] = opts.save_scans;
  writeFileAtomic(dir / drive_files::kDriveInfo, j.dump(2) + "\n");
  return res;
}

}  // namespace slamroute::simulate
