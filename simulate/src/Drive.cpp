// runDrive: the mapping vehicle drives a SUMO edge sequence among background traffic; ground
// truth, pose edges and nearby traffic are recorded at record_hz, then the drive folder is
// written (DriveOutput.cpp).
#include "slamroute/simulate/Drive.hpp"

#include <libsumo/libsumo.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <unordered_map>

#include "DriveInternal.hpp"
#include "RecordingSession.hpp"
#include "slamroute/core/DriveFolder.hpp"
#include "slamroute/core/Log.hpp"
#include "slamroute/core/Route.hpp"
#include "slamroute/core/StagingDir.hpp"
#include "slamroute/core/SumoNet.hpp"
#include "slamroute/simulate/DrivablePath.hpp"
#include "slamroute/simulate/SumoSession.hpp"
#include "slamroute/simulate/VehicleBody.hpp"
#include "slamroute/simulate/World.hpp"

namespace slamroute::simulate {
namespace {

constexpr const char* kMapper = "mapper";

bool contains(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}

struct TypeDims {
  double length, width, height;
};

/// Other vehicles whose box centre lies within `range` (horizontal) of the sensor; the other
/// mapping vehicles of a fleet are traffic to this one.
std::vector<VehicleBox> trafficAround(const std::string& self, const Vec3& sensor, double range,
                                      std::unordered_map<std::string, TypeDims>& dims_cache) {
  std::vector<VehicleBox> boxes;
  for (const auto& id : libsumo::Vehicle::getIDList()) {
    if (id == self) continue;
    const auto p = libsumo::Vehicle::getPosition3D(id);
    if (!(std::abs(p.x) < 1e7 && std::abs(p.y) < 1e7)) continue;  // teleporting: not on the road
    const std::string type = libsumo::Vehicle::getTypeID(id);
    auto it = dims_cache.find(type);
    if (it == dims_cache.end())
      it = dims_cache
               .emplace(type, TypeDims{libsumo::VehicleType::getLength(type),
                                       libsumo::VehicleType::getWidth(type),
                                       libsumo::VehicleType::getHeight(type)})
               .first;
    const double a = libsumo::Vehicle::getAngle(id) * std::numbers::pi / 180.0;
    // SUMO's position is the front bumper; the box centre is half a length behind it.
    const double cx = p.x - std::sin(a) * it->second.length / 2.0;
    const double cy = p.y - std::cos(a) * it->second.length / 2.0;
    if (std::hypot(cx - sensor.x(), cy - sensor.y()) > range) continue;
    VehicleBox b;
    b.id = id;
    b.x = cx;
    b.y = cy;
    b.z = std::abs(p.z) < 1e7 ? p.z : 0.0;
    b.heading_deg = headingFromSumoAngle(libsumo::Vehicle::getAngle(id));
    b.length = it->second.length;
    b.width = it->second.width;
    b.height = it->second.height;
    boxes.push_back(std::move(b));
  }
  return boxes;
}

void addMappers(SumoSession& sim, const std::vector<MapperToDrive>& mappers,
                const DriveConfig& dc) {
  sim.guard("adding the mapping vehicle", [&] {
    libsumo::VehicleType::copy("DEFAULT_VEHTYPE", "mapper_type");
    libsumo::VehicleType::setSpeedDeviation("mapper_type", 0.0);
    libsumo::VehicleType::setSpeedFactor("mapper_type", dc.mapper_speed_factor);
    for (const auto& m : mappers) {
      libsumo::Route::add(m.id + "_route", m.edges);
      libsumo::Vehicle::add(m.id, m.id + "_route", "mapper_type", "0", "best", "base", "max");
      // Strategic and cooperative lane changes only (no overtaking): the mapper keeps to the
      // lanes that continue its route. SUMO never leaves the route for a lane change.
      libsumo::Vehicle::setLaneChangeMode(m.id, 0b011001000101);
    }
  });
}

double routeLength(const SumoNet& net, const std::vector<std::string>& edges) {
  double len = 0.0;
  for (const auto& e : edges) len += net.findEdge(e)->length();
  return len;
}

/// Watches one mapping vehicle after each SUMO step: it must depart, keep to its route and
/// arrive without a teleport; every steps_per_record steps its pose, edge and the traffic around
/// it are recorded.
class MapperRecorder {
 public:
  MapperRecorder(const SumoNet& net, const MapperToDrive& mapper, const DriveConfig& dc,
                 const LidarSpec& spec)
      : net_(net),
        id_(mapper.id),
        edges_(mapper.edges),
        dc_(dc),
        spec_(spec),
        name_(id_ == kMapper ? "the mapping vehicle" : "the mapping vehicle " + id_),
        range_(dc.traffic_range_m > 0.0 ? dc.traffic_range_m : spec.max_range_m),
        steps_per_record_(
            std::max(1, static_cast<int>(std::lround(1.0 / (dc.record_hz * dc.step_length_s))))),
        progress_(id_ == kMapper ? "drive" : "drive " + id_,
                  static_cast<std::size_t>(routeLength(net, edges_))) {}

  /// After SUMO step number `step` at time t.
  void afterStep(long step, double t) {
    checkNotTeleported(t);
    if (!departed_ && contains(libsumo::Simulation::getDepartedIDList(), id_)) {
      departed_ = true;
      rec.depart_s = t - dc_.step_length_s;
    }
    if (contains(libsumo::Simulation::getArrivedIDList(), id_)) {
      arrived = true;
      rec.arrive_s = t;
      return;
    }
    if (!departed_) {
      if (t > 120.0)
        throw std::runtime_error(name_ + " could not be inserted on edge '" + edges_.front() +
                                 "' within 120 s");
      return;
    }
    const int ri = followRoute(step, t);
    if (step % steps_per_record_ == 0) record(t, ri);
  }

  void finish() { progress_.finish(); }
  const std::string& lastEdge() const { return edges_[static_cast<std::size_t>(last_route_index)]; }
  const std::string& name() const { return name_; }
  bool reachedRouteEnd() const { return last_route_index == static_cast<int>(edges_.size()) - 1; }

  DriveRecord rec;
  bool arrived = false;
  int last_route_index = 0;

 private:
  void checkNotTeleported(double t) const {
    if (contains(libsumo::Simulation::getStartingTeleportIDList(), id_))
      throw std::runtime_error("SUMO teleported " + name_ + " at t=" + std::to_string(t) +
                               " s (stuck on " + lastEdge() + "); the drive is not recorded");
  }

  /// The mapper's index on its route, checked to move only forward along the unchanged route.
  int followRoute(long step, double t) {
    const int ri = libsumo::Vehicle::getRouteIndex(id_);
    if (ri < last_route_index || ri >= static_cast<int>(edges_.size()))
      throw std::runtime_error(name_ + " left its route at t=" + std::to_string(t) + " s");
    if (ri != last_route_index || step % 100 == 0) {
      if (libsumo::Vehicle::getRoute(id_) != edges_)
        throw std::runtime_error("SUMO rerouted " + name_ + " at t=" + std::to_string(t) +
                                 " s; the drive is not recorded");
    }
    for (int k = last_route_index; k < ri; ++k)
      progress_m_ += net_.findEdge(edges_[static_cast<std::size_t>(k)])->length();
    last_route_index = ri;
    progress_.update(static_cast<std::size_t>(progress_m_));
    return ri;
  }

  void record(double t, int ri) {
    const auto p = libsumo::Vehicle::getPosition3D(id_);
    const Pose3 T = vehicleBodyPose(p.x, p.y, p.z, libsumo::Vehicle::getAngle(id_),
                                    libsumo::Vehicle::getSlope(id_), spec_.mount_height_m);
    const std::string lane = libsumo::Vehicle::getLaneID(id_);
    PoseEdge pe;
    pe.sumo_edge = edges_[static_cast<std::size_t>(ri)];
    pe.lane_pos_m = libsumo::Vehicle::getLanePosition(id_);
    if (!lane.empty() && lane[0] == ':') pe.lane_pos_m += net_.findEdge(pe.sumo_edge)->length();
    rec.groundtruth.push_back({t, T});
    rec.pose_edges.push_back(pe);
    rec.traffic.push_back(trafficAround(id_, T.translation(), range_, dims_));
  }

  const SumoNet& net_;
  std::string id_;
  const std::vector<std::string>& edges_;
  const DriveConfig& dc_;
  const LidarSpec& spec_;
  std::string name_;
  double range_;
  int steps_per_record_;
  Progress progress_;
  double progress_m_ = 0.0;
  bool departed_ = false;
  std::unordered_map<std::string, TypeDims> dims_;
};

/// Steps SUMO until every mapper has arrived; throws when one is still driving after max_time.
void stepUntilAllArrived(SumoSession& sim, BackgroundTraffic& traffic,
                         std::vector<MapperRecorder>& recorders, double max_time) {
  const std::string where = sim.options().net.string();
  for (long step = 1;; ++step) {
    traffic.update();
    sim.step();
    const double t = sim.time();
    bool all_arrived = true;
    for (auto& r : recorders) {
      if (!r.arrived) sim.guard("following " + r.name(), [&] { r.afterStep(step, t); });
      all_arrived = all_arrived && r.arrived;
    }
    if (all_arrived) return;
    for (const auto& r : recorders)
      if (!r.arrived && t > max_time)
        throw std::runtime_error(where + ": " + r.name() + " did not finish the route within " +
                                 std::to_string(static_cast<int>(max_time)) + " s (at edge '" +
                                 r.lastEdge() + "')");
  }
}

/// The record of an arrived mapper, checked to have driven its whole route.
DriveRecord finishedRecord(MapperRecorder& r, const std::string& where, const DriveConfig& dc) {
  r.finish();
  if (!r.reachedRouteEnd())
    throw std::runtime_error(where + ": " + r.name() +
                             " left the simulation before the end of its route (last edge '" +
                             r.lastEdge() + "')");
  DriveRecord rec = std::move(r.rec);
  if (rec.groundtruth.size() < 2)
    throw std::runtime_error(where + ": the route is too short to record a trajectory");
  makeDrivable(rec.groundtruth, dc.path_smoothing_m);
  return rec;
}

}  // namespace

std::vector<DriveRecord> recordMappers(const SumoNet& net,
                                       const std::vector<MapperToDrive>& mappers, const Config& cfg,
                                       const LidarSpec& spec, std::uint64_t seed) {
  const DriveConfig& dc = cfg.drive;
  if (!(dc.record_hz > 0.0) || !(dc.step_length_s > 0.0))
    throw std::invalid_argument("drive: record_hz and step_length_s must be > 0");
  double longest = 0.0;
  for (const auto& m : mappers) longest = std::max(longest, routeLength(net, m.edges));
  const double max_time = longest / std::max(0.1, dc.min_avg_speed_mps) + 300.0;
  SumoSession sim(
      recordingSessionOptions(net.source, seed, dc.step_length_s, dc.time_to_teleport_s));
  addMappers(sim, mappers, dc);
  BackgroundTraffic traffic(sim, net, dc.traffic_per_km, seed, "bg");

  std::vector<MapperRecorder> recorders;
  recorders.reserve(mappers.size());
  for (const auto& m : mappers) recorders.emplace_back(net, m, dc, spec);
  stepUntilAllArrived(sim, traffic, recorders, max_time);
  std::vector<DriveRecord> records;
  for (std::size_t k = 0; k < mappers.size(); ++k) {
    records.push_back(finishedRecord(recorders[k], net.source.string(), dc));
    records.back().route_length_m = routeLength(net, mappers[k].edges);
    records.back().background_vehicles = traffic.spawned();
  }
  sim.close();
  return records;
}

DriveRecord recordDrive(const SumoNet& net, const std::vector<std::string>& edges,
                        const Config& cfg, const LidarSpec& spec, std::uint64_t seed) {
  return recordMappers(net, {{kMapper, edges}}, cfg, spec, seed).front();
}

DriveResult runDrive(const DriveOptions& opts, const Config& cfg) {
  const auto wall0 = std::chrono::steady_clock::now();
  const SumoNet net = SumoNet::read(opts.net);
  const Route route = Route::readJson(opts.route_file);
  const std::vector<std::string> edges =
      drivableRoute(net, route.sumo_edges, opts.route_file.string(), opts.join_forbidden_turns);
  const LidarSpec spec = resolveLidarSpec(cfg.lidar);
  StagingDir staging(opts.out_dir, drive_files::kDriveInfo);

  logInfo("drive: " + std::to_string(edges.size()) + " edges on " + opts.net.string());
  validate(cfg.drive.body);
  DriveRecord rec = recordDrive(net, edges, cfg, spec, opts.seed);
  logInfo("drive: building the 3D world");
  const World world = World::build(net, cfg.world, opts.seed);
  // the sensor rides on the body, which stands on the world's road surface
  rec.groundtruth = vehicleSensorPoses(rec.groundtruth, world, cfg.drive.body, spec.mount_height_m);
  return committedResult(
      staging, writeDriveFolder(staging.path(), net, edges, rec, world, cfg, spec, opts, opts.seed),
      wall0);
}

}  // namespace slamroute::simulate
