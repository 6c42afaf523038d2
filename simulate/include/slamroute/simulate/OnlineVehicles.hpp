#pragma once
// Vehicles whose routes are extended online, a turn at a time, in an open SumoSession (the
// explorers of `slamroute explore`): the caller replaces the route of a vehicle by the street it
// is on (or last left) and the next few it chooses among the turns SUMO offers. No background
// traffic; a teleport or a vehicle reaching the end of its route is an error. No libsumo type
// appears here.
#include <string>
#include <vector>

#include "slamroute/core/Types.hpp"
#include "slamroute/simulate/SumoSession.hpp"

namespace slamroute::simulate {

struct OnlineVehicleState {
  bool in_net = false;  ///< departed and not arrived
  std::string edge;     ///< current non-internal edge ("" inside a junction)
  Point3 pos = Point3::Zero();
  double angle_deg = 0.0;  ///< SUMO angle (0 = north, clockwise)
  double slope_deg = 0.0;
  double odometer_m = 0.0;  ///< distance driven since departure [m]
  /// Edges of its route after the one it is on or, inside a junction, last left. Where it is
  /// comes from this, not from `edge`: a street shorter than one step's travel can be entered
  /// and left between two looks, so the vehicle may be seen only inside junctions.
  int route_edges_ahead = 0;
};

class OnlineVehicles {
 public:
  /// speed_factor: share of the speed limit the vehicles drive (no deviation).
  OnlineVehicles(SumoSession& session, double speed_factor);
  /// Adds vehicle `id` departing at time depart_s on `first` with the route [first]: call
  /// setRoute() once it is on the net, before it reaches the end of `first`.
  void add(const std::string& id, const std::string& first, double depart_s);
  /// Replaces the route; its first edge must be the one the vehicle is on or, inside a
  /// junction, the one it last left followed by the one it is turning into.
  void setRoute(const std::string& id, const std::vector<std::string>& edges);
  /// Reads the state after a step. Throws std::runtime_error when SUMO teleported the vehicle or
  /// it left the net.
  OnlineVehicleState state(const std::string& id) const;
  /// Steps the simulation and checks for teleports of the vehicles added here.
  void step();

 private:
  SumoSession& session_;
  std::vector<std::string> ids_;
  std::vector<bool> departed_;
};

}  // namespace slamroute::simulate
