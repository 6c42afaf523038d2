// runSurvey: covering routes + background traffic in SUMO; traces at trace_hz, depth frame
// poses every depth_spacing_m per survey vehicle; depth images rendered after the simulation.
#include "slamroute/simulate/Survey.hpp"

#include <libsumo/libsumo.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <random>
#include <set>
#include <sstream>

#include "RecordingSession.hpp"
#include "SurveyInternal.hpp"
#include "slamroute/core/AtomicFile.hpp"
#include "slamroute/core/DriveGraph.hpp"
#include "slamroute/core/Log.hpp"
#include "slamroute/core/StagingDir.hpp"
#include "slamroute/core/SumoNet.hpp"
#include "slamroute/simulate/SumoSession.hpp"
#include "slamroute/simulate/Traffic.hpp"

namespace slamroute::simulate {
namespace fs = std::filesystem;
namespace {

constexpr const char* kSurveyPrefix = "survey";

/// GPS-like noise: per vehicle and axis a first-order Gauss-Markov process with standard
/// deviation sigma and correlation time tau (tau = 0: white noise). The paper's CARLA traces
/// are exact; a real survey's GPS is not (~1 m), so by default the traces carry 0.5 m of it.
class GpsNoise {
 public:
  GpsNoise(double sigma, double tau, double dt, std::uint64_t seed)
      : sigma_(sigma),
        a_(tau > 0 ? std::exp(-dt / tau) : 0.0),
        rng_(seed ^ 0x5851f42d4c957f2dULL) {}
  Vec3 next(const std::string& vehicle) {
    if (!(sigma_ > 0)) return Vec3::Zero();
    std::normal_distribution<double> n(0.0, 1.0);
    auto it = state_.find(vehicle);
    if (it == state_.end()) {
      it = state_.emplace(vehicle, Vec3(n(rng_), n(rng_), n(rng_)) * sigma_).first;
      return it->second;
    }
    const double b = std::sqrt(1.0 - a_ * a_) * sigma_;
    it->second = a_ * it->second + b * Vec3(n(rng_), n(rng_), n(rng_));
    return it->second;
  }
  void forget(const std::string& vehicle) { state_.erase(vehicle); }

 private:
  double sigma_, a_;
  std::mt19937_64 rng_;
  std::map<std::string, Vec3> state_;
};

/// Angle in (-180, 180] degrees.
double normalizeDeg(double a) {
  a = std::fmod(a, 360.0);
  if (a <= -180.0) a += 360.0;
  if (a > 180.0) a -= 360.0;
  return a;
}

std::string fmt(double v, int decimals) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

struct SurveyRecord {
  std::string traces;  ///< CSV text
  std::size_t trace_rows = 0;
  std::vector<DepthShot> shots;
  std::set<std::string> visited;
  std::size_t survey_vehicles = 0;
  int background = 0;
  double sim_seconds = 0.0;
};

void addSurveyVehicles(SumoSession& sim, const DriveGraph& dg,
                       const std::vector<std::vector<std::size_t>>& routes,
                       const SurveyConfig& sc) {
  sim.guard("adding survey vehicles", [&] {
    for (std::size_t i = 0; i < routes.size(); ++i) {
      std::vector<std::string> edges;
      for (std::size_t e : routes[i]) edges.push_back(dg.edges[e].sumo_edge);
      const std::string id = kSurveyPrefix + std::to_string(i);
      libsumo::Route::add(id + "_route", edges);
      libsumo::Vehicle::add(id, id + "_route", "DEFAULT_VEHTYPE",
                            fmt(static_cast<double>(i) * sc.depart_interval_s, 1), "best", "base",
                            "max");
    }
  });
}

/// What the survey records after each SUMO step: a trace row per vehicle every trace step and a
/// depth frame pose every depth_spacing_m per survey vehicle.
class TraceRecorder {
 public:
  TraceRecorder(const SurveyConfig& sc, std::uint64_t seed)
      : sc_(sc),
        steps_per_trace_(
            std::max(1, static_cast<int>(std::lround(1.0 / sc.trace_hz / sc.step_length_s)))),
        noise_(sc.noise_sigma_m, sc.noise_tau_s, steps_per_trace_ * sc.step_length_s, seed) {
    traces_ << "t,vehicle,x,y,z,heading_deg,speed\n";
  }

  /// After SUMO step number `step` at time t.
  void afterStep(long step, double t) {
    for (const auto& id : libsumo::Simulation::getArrivedIDList()) {
      if (id.rfind(kSurveyPrefix, 0) == 0) ++arrived;
      noise_.forget(id);
      last_pos_.erase(id);
      odometer_.erase(id);
    }
    if (step % steps_per_trace_ != 0) return;
    for (const auto& id : libsumo::Vehicle::getIDList()) {
      const bool surveyor = id.rfind(kSurveyPrefix, 0) == 0;
      if (!surveyor && !sc_.record_traffic) continue;
      const std::string road = libsumo::Vehicle::getRoadID(id);
      if (road.empty()) continue;  // teleporting
      const auto p = libsumo::Vehicle::getPosition3D(id);
      const double angle = libsumo::Vehicle::getAngle(id);
      if (road[0] != ':') rec.visited.insert(road);
      writeTraceRow(t, id, p, angle);
      if (surveyor && sc_.depth_spacing_m > 0) depthFrame(t, id, road, p, angle);
    }
  }

  /// Moves the traces into the record.
  SurveyRecord finish() {
    rec.traces = traces_.str();
    return std::move(rec);
  }

  SurveyRecord rec;
  std::size_t arrived = 0;

 private:
  void writeTraceRow(double t, const std::string& id, const libsumo::TraCIPosition& p,
                     double angle) {
    const Vec3 n = noise_.next(id);
    traces_ << fmt(t, 2) << ',' << id << ',' << fmt(p.x + n.x(), 3) << ',' << fmt(p.y + n.y(), 3)
            << ',' << fmt(p.z + n.z(), 3) << ','
            << fmt(normalizeDeg(headingFromSumoAngle(angle)), 2) << ','
            << fmt(libsumo::Vehicle::getSpeed(id), 3) << '\n';
    ++rec.trace_rows;
  }

  /// A depth frame pose once the vehicle has driven depth_spacing_m since the last one (the
  /// first after half a spacing), on a normal edge.
  void depthFrame(double t, const std::string& id, const std::string& road,
                  const libsumo::TraCIPosition& p, double angle) {
    const Vec3 pos(p.x, p.y, p.z);
    auto lp = last_pos_.find(id);
    if (lp == last_pos_.end()) {
      last_pos_[id] = pos;
      odometer_[id] = 0.5 * sc_.depth_spacing_m;
      return;
    }
    odometer_[id] += (pos - lp->second).norm();
    lp->second = pos;
    if (odometer_[id] >= sc_.depth_spacing_m && road[0] != ':') {
      odometer_[id] = 0.0;
      rec.shots.push_back({t, id, road,
                           vehicleBodyPose(p.x, p.y, p.z, angle, libsumo::Vehicle::getSlope(id),
                                           sc_.camera_height_m)});
    }
  }

  const SurveyConfig& sc_;
  int steps_per_trace_;
  GpsNoise noise_;
  std::ostringstream traces_;
  std::map<std::string, double> odometer_;  // distance since the last depth frame per vehicle
  std::map<std::string, Vec3> last_pos_;
};

SurveyRecord simulate(const SumoNet& net, const DriveGraph& dg,
                      const std::vector<std::vector<std::size_t>>& routes, const SurveyConfig& sc,
                      std::uint64_t seed) {
  SumoSession sim(
      recordingSessionOptions(net.source, seed, sc.step_length_s, sc.time_to_teleport_s));
  addSurveyVehicles(sim, dg, routes, sc);
  BackgroundTraffic traffic(sim, net, sc.traffic_per_km, seed, "bg");
  TraceRecorder recorder(sc, seed);
  Progress progress("survey", routes.size());
  for (long step = 1; recorder.arrived < routes.size(); ++step) {
    traffic.update();
    sim.step();
    const double t = sim.time();
    sim.guard("recording traces", [&] { recorder.afterStep(step, t); });
    progress.update(recorder.arrived);
    if (t > sc.max_time_s) {
      logWarn("survey: stopped at the time limit " + fmt(sc.max_time_s, 0) + " s with " +
              std::to_string(routes.size() - recorder.arrived) + " survey vehicles still driving");
      break;
    }
  }
  progress.finish();
  SurveyRecord rec = recorder.finish();
  rec.survey_vehicles = routes.size();
  rec.background = traffic.spawned();
  rec.sim_seconds = sim.time();
  sim.close();
  return rec;
}

std::uint64_t folderBytes(const fs::path& dir) {
  std::uint64_t total = 0;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) total += e.file_size();
  return total;
}

/// What the survey drove: vehicles, trace rows and the drivable edges visited (the rest listed
/// in `unvisited`), against the `planned` covering routes.
SurveyResult surveyFigures(const SurveyRecord& rec, const DriveGraph& dg,
                           const std::set<std::size_t>& planned,
                           std::vector<std::string>& unvisited) {
  SurveyResult res;
  res.survey_vehicles = rec.survey_vehicles;
  res.background_vehicles = static_cast<std::size_t>(rec.background);
  res.trace_rows = rec.trace_rows;
  res.drivable_edges = dg.numEdges();
  for (const auto& e : dg.edges) {
    if (rec.visited.count(e.sumo_edge))
      ++res.visited_edges;
    else
      unvisited.push_back(e.sumo_edge);
  }
  res.coverage_pct = res.drivable_edges ? 100.0 * res.visited_edges / res.drivable_edges : 0.0;
  res.planned_coverage_pct = res.drivable_edges ? 100.0 * planned.size() / res.drivable_edges : 0.0;
  res.sim_seconds = rec.sim_seconds;
  res.depth_frames = rec.shots.size();
  return res;
}

void writeSurveyJson(const fs::path& path, const SurveyOptions& opts, const SurveyConfig& sc,
                     const SurveyResult& res, const std::vector<std::string>& unvisited) {
  nlohmann::json j;
  j["net"] = fs::absolute(opts.net).lexically_normal().string();
  j["seed"] = opts.seed;
  j["survey_vehicles"] = res.survey_vehicles;
  j["background_vehicles"] = res.background_vehicles;
  j["trace_rows"] = res.trace_rows;
  j["trace_hz"] = sc.trace_hz;
  j["noise_sigma_m"] = sc.noise_sigma_m;
  j["noise_tau_s"] = sc.noise_tau_s;
  j["depth_frames"] = res.depth_frames;
  j["depth_spacing_m"] = sc.depth_spacing_m;
  j["drivable_edges"] = res.drivable_edges;
  j["visited_edges"] = res.visited_edges;
  j["coverage_pct"] = res.coverage_pct;
  j["planned_coverage_pct"] = res.planned_coverage_pct;
  j["unvisited_edges"] = unvisited;
  j["sim_seconds"] = res.sim_seconds;
  writeFileAtomic(path, j.dump(2) + "\n");
}

}  // namespace

SurveyResult runSurvey(const SurveyOptions& opts, const Config& cfg) {
  const auto wall0 = std::chrono::steady_clock::now();
  const SurveyConfig& sc = cfg.survey;
  if (!(sc.trace_hz > 0) || !(sc.step_length_s > 0) || !(sc.route_length_m > 0))
    throw std::invalid_argument("survey: trace_hz, step_length_s and route_length_m must be > 0");
  const SumoNet net = SumoNet::read(opts.net);
  const DriveGraph dg = DriveGraph::fromNet(net);
  StagingDir staging(opts.out_dir, "survey.json");

  const auto routes = coveringRoutes(dg, sc.route_length_m);
  std::set<std::size_t> planned;
  for (const auto& r : routes) planned.insert(r.begin(), r.end());
  logInfo("survey: " + std::to_string(routes.size()) + " covering routes over " +
          std::to_string(dg.numEdges()) + " drivable edges of " + opts.net.string());

  const SurveyRecord rec = simulate(net, dg, routes, sc, opts.seed);
  std::vector<std::string> unvisited;
  SurveyResult res = surveyFigures(rec, dg, planned, unvisited);

  writeFileAtomic(staging.path() / "traces.csv", rec.traces);
  writeDepthFrames(staging.path() / "depth", net, cfg, opts.seed, rec.shots);
  writeSurveyJson(staging.path() / "survey.json", opts, sc, res, unvisited);
  res.bytes_written = folderBytes(staging.path());
  return committedResult(staging, std::move(res), wall0);
}

}  // namespace slamroute::simulate
