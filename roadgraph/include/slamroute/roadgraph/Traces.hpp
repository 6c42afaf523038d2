#pragma once
// Location traces of survey vehicles: traces.csv (`t,vehicle,x,y,z,heading_deg,speed`, metres in
// the net's projected frame) or SUMO FCD XML (`sumo --fcd-output`).
#include <filesystem>
#include <string>
#include <vector>

#include "slamroute/core/Types.hpp"

namespace slamroute::roadgraph {

struct TracePoint {
  double t = 0.0;               ///< [s]
  int vehicle = 0;              ///< index into Traces::vehicles
  Point3 pos = Point3::Zero();  ///< [m]
  double heading_deg = 0.0;     ///< 0 = +x (east), counter-clockwise [deg]
  double speed = 0.0;           ///< [m/s]
};

struct Traces {
  std::vector<TracePoint> points;
  std::vector<std::string> vehicles;  ///< vehicle names
  std::string source;                 ///< file they were read from (for messages)
};

/// Reads traces.csv. Throws std::runtime_error / std::invalid_argument naming the file and line
/// on a missing file, a missing column, an unparsable number.
Traces readTracesCsv(const std::filesystem::path& path);
/// Reads SUMO FCD XML; SUMO's navigation angle (0 = north, clockwise) becomes heading_deg.
Traces readFcdXml(const std::filesystem::path& path);
/// Picks the reader by content (XML or CSV).
Traces readTraces(const std::filesystem::path& path);
/// Trace point indices by vehicle, then time (stable: equal times keep file order). The order
/// every per-vehicle pass over the traces walks in.
std::vector<std::size_t> byVehicleThenTime(const Traces& traces);
/// Throws std::invalid_argument naming `where` for empty or one-point traces and NaN/inf values.
void checkTraces(const Traces& traces, const std::string& where);

}  // namespace slamroute::roadgraph
