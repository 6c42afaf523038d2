#pragma once
// The folder of a fleet's drive: DIR/vehicle_K/ per vehicle (each an ordinary drive folder,
// DriveFolder.hpp) and DIR/fleet.json naming them with their lengths and times.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace slamroute {

inline constexpr const char* kFleetDriveInfo = "fleet.json";

struct FleetDriveVehicle {
  std::string id;      ///< SUMO vehicle id (mapper_K)
  std::string folder;  ///< its drive folder, relative to the fleet folder (vehicle_K)
  double route_length_m = 0.0;
  double driven_m = 0.0;
  double depart_s = 0.0, arrive_s = 0.0;  ///< simulation times, shared by the fleet
  std::size_t frames = 0;
};

struct FleetDriveInfo {
  std::string net;  ///< absolute path of the SUMO net
  std::uint64_t seed = 0;
  std::vector<FleetDriveVehicle> vehicles;

  /// Latest arrival minus earliest departure [s]: how long the campaign takes.
  double makespanSeconds() const;
  /// True when DIR/fleet.json exists.
  static bool isFleetFolder(const std::filesystem::path& dir);
  /// Reads DIR/fleet.json; throws std::invalid_argument naming the file when it is malformed,
  /// names no vehicle or a vehicle folder that does not exist.
  static FleetDriveInfo read(const std::filesystem::path& dir);
  /// Writes DIR/fleet.json atomically.
  void write(const std::filesystem::path& dir) const;
  static std::string folderName(std::size_t index) { return "vehicle_" + std::to_string(index); }
};

}  // namespace slamroute
