#pragma once
// RAII wrapper around libsumo (SUMO as a library, C++). libsumo holds ONE simulation per
// process in global state, so at most one SumoSession may be open at a time: opening a second
// throws. The destructor closes the simulation. Errors from SUMO (libsumo::TraCIException,
// ProcessError, FatalError — all std::runtime_error) are rethrown as std::runtime_error naming
// the net. No libsumo type appears here: Survey.cpp / Drive.cpp call libsumo inside guard().
#include <cstdint>
#include <filesystem>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "slamroute/core/Types.hpp"

namespace slamroute {
struct SumoNet;
}

namespace slamroute::simulate {

struct SumoSessionOptions {
  std::filesystem::path net;            ///< .net.xml(.gz)
  std::uint64_t seed = 42;              ///< SUMO's --seed (taken modulo 2^31)
  double step_length_s = 0.1;           ///< simulation step [s]
  double time_to_teleport_s = 300.0;    ///< SUMO's --time-to-teleport; <= 0 disables teleports
  bool warnings = false;                ///< false passes --no-warnings
  std::vector<std::string> extra_args;  ///< appended to the SUMO command line
};

class SumoSession {
 public:
  /// Starts SUMO on the net (sets SUMO_HOME=/usr/share/sumo when unset). Throws
  /// std::runtime_error when another session is open or SUMO fails to load the net.
  explicit SumoSession(SumoSessionOptions opts);
  ~SumoSession();
  SumoSession(const SumoSession&) = delete;
  SumoSession& operator=(const SumoSession&) = delete;

  /// Advances the simulation by one step.
  void step();
  /// Simulation time [s].
  double time() const;
  double stepLength() const { return opts_.step_length_s; }
  /// Closes the simulation; idempotent. After close() another session may be opened.
  void close();
  bool isOpen() const { return open_; }
  const SumoSessionOptions& options() const { return opts_; }

  /// True while any session of this process is open.
  static bool anyOpen();

  /// Runs `f` (which calls libsumo) and turns any exception into std::runtime_error
  /// "NET: WHAT: message".
  template <class F>
  auto guard(const std::string& what, F&& f) const -> decltype(f()) {
    try {
      return f();
    } catch (const std::exception& e) {
      throw std::runtime_error(opts_.net.string() + ": " + what + ": " + e.what());
    }
  }

 private:
  SumoSessionOptions opts_;
  bool open_ = false;
};

/// Pose of a body `height_m` straight above SUMO's vehicle reference point (the middle of the
/// front bumper on the road surface) at (x, y, z): x along the heading (SUMO angle: 0 = north,
/// clockwise), pitched with the road's slope (positive uphill: the body x axis then points up,
/// hence the rotation by -pitch about body y), z up.
Pose3 vehicleBodyPose(double x, double y, double z, double sumo_angle_deg, double slope_deg,
                      double height_m);

/// Background traffic from random trips, generated in C++ from a seed (deterministic; no
/// randomTrips.py): keeps about `vehicles_per_km` vehicles per km of drivable road on the net,
/// each on a SUMO shortest route between two random edges of the largest strongly connected
/// part; vehicles that arrive are replaced. Vehicle ids are "<prefix><n>".
class BackgroundTraffic {
 public:
  BackgroundTraffic(const SumoSession& session, const SumoNet& net, double vehicles_per_km,
                    std::uint64_t seed, std::string prefix = "bg");
  /// Call once per step (before SumoSession::step()): inserts vehicles up to the target.
  void update();
  int target() const { return target_; }
  int spawned() const { return spawned_; }
  const std::string& prefix() const { return prefix_; }
  bool owns(const std::string& vehicle_id) const { return vehicle_id.rfind(prefix_, 0) == 0; }

 private:
  const SumoSession& session_;
  std::vector<std::string> edges_;  ///< candidate origins/destinations
  std::mt19937_64 rng_;
  std::string prefix_;
  int target_ = 0;
  int spawned_ = 0;
  int live_ = 0;
};

}  // namespace slamroute::simulate
