// fleet.json of a fleet's drive folder.
#include "slamroute/core/FleetDrive.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "JsonFile.hpp"
#include "slamroute/core/AtomicFile.hpp"

namespace slamroute {
using nlohmann::json;
namespace fs = std::filesystem;

double FleetDriveInfo::makespanSeconds() const {
  if (vehicles.empty()) return 0.0;
  double first = vehicles.front().depart_s, last = vehicles.front().arrive_s;
  for (const auto& v : vehicles) {
    first = std::min(first, v.depart_s);
    last = std::max(last, v.arrive_s);
  }
  return last - first;
}

bool FleetDriveInfo::isFleetFolder(const fs::path& dir) {
  return fs::is_regular_file(dir / kFleetDriveInfo);
}

FleetDriveInfo FleetDriveInfo::read(const fs::path& dir) {
  const fs::path path = dir / kFleetDriveInfo;
  const json j = detail::readJsonFile(path);
  FleetDriveInfo f;
  try {
    f.net = j.at("net").get<std::string>();
    f.seed = j.at("seed").get<std::uint64_t>();
    for (const auto& v : j.at("vehicles")) {
      FleetDriveVehicle fv;
      fv.id = v.at("id").get<std::string>();
      fv.folder = v.at("folder").get<std::string>();
      fv.route_length_m = v.at("route_length_m").get<double>();
      fv.driven_m = v.at("driven_m").get<double>();
      fv.depart_s = v.at("depart_s").get<double>();
      fv.arrive_s = v.at("arrive_s").get<double>();
      fv.frames = v.at("frames").get<std::size_t>();
      f.vehicles.push_back(std::move(fv));
    }
  } catch (const json::exception& e) {
    throw std::invalid_argument(path.string() + ": " + detail::jsonErrorText(e));
  }
  if (f.vehicles.empty()) throw std::invalid_argument(path.string() + ": no vehicles");
  for (const auto& v : f.vehicles)
    if (!fs::is_directory(dir / v.folder))
      throw std::invalid_argument(path.string() + ": vehicle folder '" + v.folder +
                                  "' does not exist");
  return f;
}

void FleetDriveInfo::write(const fs::path& dir) const {
  json vs = json::array();
  for (const auto& v : vehicles)
    vs.push_back({{"id", v.id},
                  {"folder", v.folder},
                  {"route_length_m", v.route_length_m},
                  {"driven_m", v.driven_m},
                  {"depart_s", v.depart_s},
                  {"arrive_s", v.arrive_s},
                  {"duration_s", v.arrive_s - v.depart_s},
                  {"frames", v.frames}});
  const json j = {
      {"net", net}, {"seed", seed}, {"vehicles", vs}, {"makespan_s", makespanSeconds()}};
  writeFileAtomic(dir / kFleetDriveInfo, j.dump(2) + "\n");
}

}  // namespace slamroute
