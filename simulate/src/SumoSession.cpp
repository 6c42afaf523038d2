// SumoSession: one libsumo simulation per process, opened and closed by RAII.
#include "slamroute/simulate/SumoSession.hpp"

#include "RecordingSession.hpp"

#include <libsumo/libsumo.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <sstream>

namespace slamroute::simulate {
namespace {

std::atomic<bool> g_open{false};  // libsumo's simulation is process-global

std::string num(double v) {
  std::ostringstream os;
  os.precision(10);
  os << v;
  return os.str();
}

}  // namespace

SumoSession::SumoSession(SumoSessionOptions opts) : opts_(std::move(opts)) {
  if (g_open.exchange(true))
    throw std::runtime_error(opts_.net.string() +
                             ": a SUMO session is already open in this process (libsumo runs one "
                             "simulation per process)");
  try {
    if (!std::filesystem::exists(opts_.net)) throw std::runtime_error("net file not found");
    if (!(opts_.step_length_s > 0.0)) throw std::runtime_error("step length must be > 0");
    if (!std::getenv("SUMO_HOME")) setenv("SUMO_HOME", "/usr/share/sumo", 0);
    std::vector<std::string> args = {
        "-n",
        opts_.net.string(),
        "--begin",
        "0",
        "--step-length",
        num(opts_.step_length_s),
        "--seed",
        std::to_string(opts_.seed % 2147483647ULL),
        "--no-step-log",
        "true",
        "--duration-log.disable",
        "true",
        "--xml-validation",
        "never",
        "--xml-validation.net",
        "never",
        "--time-to-teleport",
        num(opts_.time_to_teleport_s > 0 ? opts_.time_to_teleport_s : -1),
        // Collisions are logged, not resolved by teleporting (a teleport would be an error
        // for the mapping vehicle).
        "--collision.action",
        "warn",
    };
    if (!opts_.warnings) args.insert(args.end(), {"--no-warnings", "true"});
    args.insert(args.end(), opts_.extra_args.begin(), opts_.extra_args.end());
    libsumo::Simulation::load(args);
    if (!libsumo::Simulation::isLoaded()) throw std::runtime_error("SUMO did not load the net");
  } catch (const std::exception& e) {
    g_open = false;
    throw std::runtime_error(opts_.net.string() + ": cannot start SUMO: " + e.what());
  }
  open_ = true;
}

SumoSession::~SumoSession() {
  try {
    close();
  } catch (...) {
    // never throw from a destructor
  }
}

void SumoSession::step() {
  if (!open_) throw std::runtime_error(opts_.net.string() + ": SUMO session is closed");
  guard("simulation step", [] { libsumo::Simulation::step(); });
}

double SumoSession::time() const {
  if (!open_) throw std::runtime_error(opts_.net.string() + ": SUMO session is closed");
  return guard("simulation time", [] { return libsumo::Simulation::getTime(); });
}

void SumoSession::close() {
  if (!open_) return;
  open_ = false;
  try {
    libsumo::Simulation::close();
  } catch (const std::exception& e) {
    g_open = false;
    throw std::runtime_error(opts_.net.string() + ": closing SUMO: " + e.what());
  }
  g_open = false;
}

bool SumoSession::anyOpen() { return g_open.load(); }

Pose3 vehicleBodyPose(double x, double y, double z, double sumo_angle_deg, double slope_deg,
                      double height_m) {
  const double yaw = (90.0 - sumo_angle_deg) * std::numbers::pi / 180.0;
  const double pitch = slope_deg * std::numbers::pi / 180.0;
  Pose3 T = Pose3::Identity();
  T.linear() = (Eigen::AngleAxisd(yaw, Vec3::UnitZ()) * Eigen::AngleAxisd(-pitch, Vec3::UnitY()))
                   .toRotationMatrix();
  T.translation() = Vec3(x, y, z + height_m);
  return T;
}

SumoSessionOptions recordingSessionOptions(const std::filesystem::path& net, std::uint64_t seed,
                                           double step_length_s, double time_to_teleport_s) {
  SumoSessionOptions so;
  so.net = net;
  so.seed = seed;
  so.step_length_s = step_length_s;
  so.time_to_teleport_s = time_to_teleport_s;
  so.extra_args = {"--lanechange.duration", "2"};
  return so;
}

}  // namespace slamroute::simulate
