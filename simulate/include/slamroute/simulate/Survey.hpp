#pragma once
// `slamroute survey`: SUMO vehicles drive routes that together cover the drivable net, among
// background traffic; the survey folder receives
//   traces.csv        t,vehicle,x,y,z,heading_deg,speed at trace_hz (10 Hz); metres in the net
//                     frame with GPS-like noise; heading_deg in the math convention of
//                     Traffic.hpp (0 = +x/east, counter-clockwise) = 90 - SUMO angle; speed [m/s]
//   depth/index.csv   frame,t,vehicle,x,y,z,qx,qy,qz,qw,file — the exact camera pose
//                     T_world_camera (DepthCamera's frame convention) and the PNG file name
//   depth/NNNNNN.png  16-bit depth in millimetres (DepthCamera), 0 = no return
//   depth/frame_edges.csv  frame,sumo_edge — the SUMO edge each frame was taken on (validation)
//   survey.json       vehicles, drivable edges, edges visited, coverage share, frames, …
// The folder is written beside its target and renamed into place (nothing half-written).
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "slamroute/simulate/Config.hpp"

namespace slamroute {
struct DriveGraph;
}

namespace slamroute::simulate {

struct SurveyOptions {
  std::filesystem::path net;
  std::filesystem::path out_dir;
  std::uint64_t seed = 42;
};

struct SurveyResult {
  std::filesystem::path out_dir;
  std::size_t survey_vehicles = 0;  ///< vehicles on covering routes
  std::size_t background_vehicles = 0;
  std::size_t trace_rows = 0;
  std::size_t depth_frames = 0;
  std::size_t drivable_edges = 0;     ///< passenger edges of the net
  std::size_t visited_edges = 0;      ///< drivable edges some recorded vehicle drove on
  double coverage_pct = 0.0;          ///< visited / drivable [%]
  double planned_coverage_pct = 0.0;  ///< share the covering routes contain [%]
  double sim_seconds = 0.0;
  double wall_seconds = 0.0;
  std::uint64_t bytes_written = 0;
};

/// Routes (edge indices of `g`, each consecutive pair an allowed turn) that together contain as
/// many edges as reachable and every allowed turn round a bend (through a junction with two
/// arms, one arm to the other, not a U-turn), turning places included: greedy — from the
/// current edge go to the nearest edge or such turn not yet driven (Dijkstra over the turn
/// graph), until a route is max_length_m long, then start a new route on an
/// uncovered edge (edges nothing leads to first), or, once every edge is driven, on an edge
/// whose bend is left.
std::vector<std::vector<std::size_t>> coveringRoutes(const DriveGraph& g, double max_length_m);

/// Runs the survey (reads the net, simulates, renders depth frames, writes out_dir).
SurveyResult runSurvey(const SurveyOptions& opts, const Config& cfg);

}  // namespace slamroute::simulate
