#include "slamroute/export/ExportFleet.hpp"

#include <stdexcept>
#include <string>

namespace slamroute::exports {
namespace fs = std::filesystem;

namespace {

const char* const kVehicleInfix = ".vehicle_";

/// True when `name` is STEM.vehicle_<digits> followed by one of the crew file suffixes.
bool isVehicleFileName(const std::string& name, const std::string& stem) {
  const std::string prefix = stem + kVehicleInfix;
  if (name.rfind(prefix, 0) != 0) return false;
  const std::size_t digits_end = name.find_first_not_of("0123456789", prefix.size());
  if (digits_end == prefix.size() || digits_end == std::string::npos) return false;
  const std::string suffix = name.substr(digits_end);
  return suffix == ".gpx" || suffix == ".kml" || suffix == "_instructions.md" ||
         suffix == "_instructions.csv";
}

}  // namespace

fs::path vehicleRoutePath(const fs::path& route_json, std::size_t k) {
  return besideRoute(route_json, kVehicleInfix + std::to_string(k) + ".json");
}

RouteFileTexts fleetFileTexts(const SumoNet& net, const FleetRoute& fleet,
                              const fs::path& route_json, const RouteExportOptions& opt) {
  RouteFileTexts out;
  const std::size_t K = fleet.vehicles.size();
  for (std::size_t k = 0; k < K; ++k) {
    const Route& r = fleet.vehicles[k];
    if (r.sumo_edges.empty())
      throw std::invalid_argument(route_json.string() + ": vehicle " + std::to_string(k) +
                                  " has no SUMO edges (plan the fleet with --net)");
    const std::string title = "vehicle " + std::to_string(k) + " of " + std::to_string(K) + " (" +
                              FleetRoute::vehicleId(k) + "): " + r.planner + " route";
    RouteFileTexts one = routeFileTexts(net, r, vehicleRoutePath(route_json, k), title, opt);
    for (auto& f : one.files) out.files.push_back(std::move(f));
    out.note = one.note;  // the same net for every vehicle: one note
  }
  return out;
}

std::vector<fs::path> existingVehicleFiles(const fs::path& route_json) {
  const fs::path dir = route_json.has_parent_path() ? route_json.parent_path() : fs::path(".");
  std::vector<fs::path> out;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec))
    if (isVehicleFileName(entry.path().filename().string(), route_json.stem().string()))
      out.push_back(entry.path());
  return out;
}

}  // namespace slamroute::exports
