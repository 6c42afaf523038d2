#include "CrewFiles.hpp"

#include <algorithm>
#include "Commands.hpp"

#include "slamroute/core/AtomicFile.hpp"
#include "slamroute/core/FleetRoute.hpp"
#include "slamroute/core/Log.hpp"
#include "slamroute/core/Route.hpp"
#include "slamroute/export/ExportFleet.hpp"
#include "slamroute/export/ExportRoute.hpp"

namespace slamroute::cli {
namespace {

exports::RouteExportOptions exportOptions(const Context& ctx, const std::string& geo_origin) {
  exports::RouteExportOptions opt;
  if (!geo_origin.empty()) opt.geo_origin = exports::parseGeoOrigin(geo_origin, "--geo-origin");
  opt.instructions.loop_min_travel_m = ctx.cfg.rl.eif.loop_min_travel_m;
  return opt;
}

}  // namespace

std::string checkGeoOrigin(const std::string& text) {
  try {
    exports::parseGeoOrigin(text, "--geo-origin");
    return "";
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
}

std::string writeCrewFiles(const Context& ctx, const SumoNet& net,
                           const std::filesystem::path& route_json, const std::string& geo_origin) {
  const auto res = exports::exportRoute(net, Route::readJson(route_json), route_json,
                                        exportOptions(ctx, geo_origin));
  std::string names;
  for (const auto& p : res.written) names += (names.empty() ? "" : ", ") + p.filename().string();
  logInfo("wrote " + names + " beside " + route_json.filename().string());
  return res.note;
}

std::string stageFleetCrewFiles(const Context& ctx, const SumoNet& net, const FleetRoute& fleet,
                                const std::filesystem::path& route_json,
                                const std::string& geo_origin, AtomicFileSet& files) {
  const exports::RouteFileTexts texts =
      exports::fleetFileTexts(net, fleet, route_json, exportOptions(ctx, geo_origin));
  std::vector<std::filesystem::path> written;  // file names: the folder is route_json's
  for (const auto& [p, text] : texts.files) {
    writeFileAtomic(files.staged(p), text);
    written.push_back(p.filename());
  }
  for (const auto& old : exports::existingVehicleFiles(route_json))
    if (std::find(written.begin(), written.end(), old.filename()) == written.end())
      files.dropAtCommit(old);
  logInfo("crew files of " + std::to_string(fleet.vehicles.size()) + " vehicles beside " +
          route_json.filename().string() + ": " + written.front().string() + " .. " +
          written.back().string() + " (" + std::to_string(written.size()) + " files)");
  return texts.note;
}

std::string writeFleetCrewFiles(const Context& ctx, const SumoNet& net,
                                const std::filesystem::path& route_json,
                                const std::string& geo_origin) {
  const FleetRoute fleet = FleetRoute::readJson(route_json);
  AtomicFileSet files;
  const std::string note = stageFleetCrewFiles(ctx, net, fleet, route_json, geo_origin, files);
  files.commit();
  return note;
}

}  // namespace slamroute::cli
