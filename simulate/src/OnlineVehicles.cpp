// OnlineVehicles: libsumo vehicles whose route grows by one chosen edge at a time.
#include "slamroute/simulate/OnlineVehicles.hpp"

#include <libsumo/libsumo.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace slamroute::simulate {
namespace {
constexpr const char* kType = "explorer_type";

bool contains(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}
}  // namespace

OnlineVehicles::OnlineVehicles(SumoSession& session, double speed_factor) : session_(session) {
  session_.guard("adding the explorer vehicle type", [&] {
    libsumo::VehicleType::copy("DEFAULT_VEHTYPE", kType);
    libsumo::VehicleType::setSpeedDeviation(kType, 0.0);
    libsumo::VehicleType::setSpeedFactor(kType, speed_factor);
  });
}

void OnlineVehicles::add(const std::string& id, const std::string& first, double depart_s) {
  session_.guard("adding explorer " + id, [&] {
    libsumo::Route::add(id + "_route", {first});
    libsumo::Vehicle::add(id, id + "_route", kType, std::to_string(depart_s), "best", "base",
                          "max");
    // Strategic and cooperative lane changes only: the vehicle keeps to the lanes of its turn.
    libsumo::Vehicle::setLaneChangeMode(id, 0b011001000101);
  });
  ids_.push_back(id);
  departed_.push_back(false);
}

void OnlineVehicles::setRoute(const std::string& id, const std::vector<std::string>& edges) {
  session_.guard("extending the route of " + id, [&] { libsumo::Vehicle::setRoute(id, edges); });
}

void OnlineVehicles::step() {
  session_.step();
  session_.guard("following the explorers", [&] {
    const auto teleports = libsumo::Simulation::getStartingTeleportIDList();
    const auto departed = libsumo::Simulation::getDepartedIDList();
    const auto arrived = libsumo::Simulation::getArrivedIDList();
    for (std::size_t i = 0; i < ids_.size(); ++i) {
      if (contains(teleports, ids_[i]))
        throw std::runtime_error("SUMO teleported explorer " + ids_[i] +
                                 " at t=" + std::to_string(session_.time()) + " s");
      if (contains(departed, ids_[i])) departed_[i] = true;
      if (contains(arrived, ids_[i]))
        throw std::runtime_error("explorer " + ids_[i] + " reached the end of its route at t=" +
                                 std::to_string(session_.time()) + " s");
    }
  });
}

OnlineVehicleState OnlineVehicles::state(const std::string& id) const {
  const auto it = std::find(ids_.begin(), ids_.end(), id);
  if (it == ids_.end()) throw std::runtime_error("unknown explorer " + id);
  OnlineVehicleState s;
  if (!departed_[static_cast<std::size_t>(it - ids_.begin())]) return s;
  session_.guard("reading explorer " + id, [&] {
    s.in_net = true;
    const std::string road = libsumo::Vehicle::getRoadID(id);
    if (!road.empty() && road[0] != ':') s.edge = road;
    const auto p = libsumo::Vehicle::getPosition3D(id);
    s.pos = Point3(p.x, p.y, p.z);
    s.angle_deg = libsumo::Vehicle::getAngle(id);
    s.slope_deg = libsumo::Vehicle::getSlope(id);
    s.odometer_m = libsumo::Vehicle::getDistance(id);
    // SUMO keeps the edges driven before the last setRoute in front of the route it was given
    s.route_edges_ahead = static_cast<int>(libsumo::Vehicle::getRoute(id).size()) - 1 -
                          libsumo::Vehicle::getRouteIndex(id);
  });
  return s;
}

}  // namespace slamroute::simulate
