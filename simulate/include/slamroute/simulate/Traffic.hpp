#pragma once
// Moving traffic as seen by the sensors: one oriented box per vehicle per frame.
// A drive records them in DIR/traffic.csv (written by the drive command, read by
// SimulatedScanSource to put the same vehicles into regenerated scans):
//
//   frame,t,id,x,y,z,heading_deg,length,width,height
//
// frame = index of the ground-truth pose (line of groundtruth.tum, 0-based) the boxes belong
// to; t = its time [s]; x,y,z = centre of the box's BOTTOM face (on the road) in the net frame
// [m]; heading_deg = SUMO angle convention converted to math: 0 = +x (east), counter-clockwise
// positive, i.e. heading_deg = 90 - sumo_angle; length along heading, width across, height up [m].
// The ego vehicle itself is not listed. Frames without traffic have no rows.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace slamroute::simulate {

inline constexpr const char* kTrafficFile = "traffic.csv";

struct VehicleBox {
  std::string id;
  double x = 0, y = 0, z = 0;                      ///< bottom-face centre, net frame [m]
  double heading_deg = 0;                          ///< 0 = +x, counter-clockwise [deg]
  double length = 4.5, width = 1.8, height = 1.5;  ///< [m]
};

/// Boxes per frame: frames[i] = vehicles around ground-truth pose i.
using TrafficFrames = std::vector<std::vector<VehicleBox>>;

/// Writes the CSV (header + one row per box) atomically. `times[i]` is frame i's time; must have
/// frames.size() entries. Throws std::invalid_argument on a size mismatch.
void writeTrafficCsv(const std::filesystem::path& path, const TrafficFrames& frames,
                     const std::vector<double>& times);

/// Reads the CSV; the result has max(frame)+1 entries, at least `min_frames`. Throws
/// std::runtime_error naming the file and line on bad input.
TrafficFrames readTrafficCsv(const std::filesystem::path& path, std::size_t min_frames = 0);

/// Math heading [deg] (0 = +x, CCW) from a SUMO/TraCI angle (0 = north, clockwise).
inline double headingFromSumoAngle(double sumo_angle_deg) { return 90.0 - sumo_angle_deg; }

}  // namespace slamroute::simulate
