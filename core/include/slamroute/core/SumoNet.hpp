#pragma once
// Plain model of a SUMO road network (.net.xml / .net.xml.gz), read with pugixml.
// No libsumo here: every module (including rl/, which must build without SUMO) can use it.
#include <filesystem>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "slamroute/core/Types.hpp"

namespace slamroute {

struct SumoJunction {
  std::string id;
  std::string type;             ///< priority, traffic_light, dead_end, internal, ...
  Point3 pos = Point3::Zero();  ///< x, y, z (z = 0 when the net has none) [m]
  std::vector<std::string> inc_lanes;
};

struct SumoLane {
  std::string id;
  int index = 0;
  double length_m = 0.0;
  double speed_mps = 0.0;
  double width_m = 3.2;
  std::vector<std::string> allow, disallow;  ///< raw vehicle classes as written in the net
  Polyline shape;                            ///< z = 0 where the net gives 2D points
  bool allowsPassenger() const;
};

struct SumoEdge {
  std::string id;
  std::string from, to;  ///< junction ids (empty for internal edges)
  std::string function;  ///< "" (normal), internal, connector, walkingarea, crossing
  std::string type;
  std::string name;  ///< street name (netconvert's `name`, from OSM); may be empty
  int priority = -1;
  std::vector<SumoLane> lanes;
  Polyline shape;  ///< the centre lane's shape (travel direction)
  bool isInternal() const { return !function.empty() && function != "normal"; }
  bool allowsPassenger() const;  ///< any lane allows passenger cars
  double length() const;         ///< mean lane length [m]
  double speed() const;          ///< max lane speed [m/s]
};

struct SumoConnection {
  std::string from, to;  ///< edge ids
  int from_lane = 0, to_lane = 0;
  std::string dir;            ///< s, l, r, t (U-turn), L, R, invalid
  std::string via;            ///< internal lane id, may be empty
  double via_length_m = 0.0;  ///< internal lanes from `via` to the next normal edge [m]
};

/// A <roundabout>: its junctions and the edges that circle it.
struct SumoRoundabout {
  std::vector<std::string> nodes, edges;
};

struct SumoLocation {
  Point2 net_offset = Point2::Zero();
  std::string conv_boundary, orig_boundary, proj_parameter;  ///< proj may be "!"
};

struct SumoNet {
  std::filesystem::path source;
  SumoLocation location;
  std::vector<SumoJunction> junctions;      ///< non-internal junctions
  std::vector<SumoEdge> edges;              ///< non-internal edges only
  std::vector<SumoConnection> connections;  ///< between non-internal edges
  std::vector<SumoRoundabout> roundabouts;
  std::unordered_map<std::string, std::size_t> junction_index, edge_index;

  const SumoEdge* findEdge(const std::string& id) const;
  const SumoJunction* findJunction(const std::string& id) const;
  /// Passenger-car turn from edge `from` onto edge `to` allowed by some <connection>.
  bool turnAllowed(const std::string& from, const std::string& to) const;

  /// Reads a .net.xml or .net.xml.gz. Throws std::runtime_error / std::invalid_argument with a
  /// one-line message naming the file: missing, not XML, not a SUMO net, truncated gzip.
  static SumoNet read(const std::filesystem::path& path);

 private:
  std::unordered_map<std::string, std::vector<std::string>> turns_;  ///< from edge -> to edges
  friend struct SumoNetBuilder;
};

/// True when the vehicle class list semantics of a lane admit "passenger".
bool passengerAllowed(const std::vector<std::string>& allow,
                      const std::vector<std::string>& disallow);

}  // namespace slamroute
