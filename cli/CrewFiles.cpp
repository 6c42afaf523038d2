#include "CrewFiles.hpp"

#include "Commands.hpp"
#include "slamroute/core/Log.hpp"
#include "slamroute/core/Route.hpp"
#include "slamroute/export/ExportRoute.hpp"

namespace slamroute::cli {

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
  exports::RouteExportOptions opt;
  if (!geo_origin.empty()) opt.geo_origin = exports::parseGeoOrigin(geo_origin, "--geo-origin");
  opt.instructions.loop_min_travel_m = ctx.cfg.rl.eif.loop_min_travel_m;
  const auto res = exports::exportRoute(net, Route::readJson(route_json), route_json, opt);
  std::string names;
  for (const auto& p : res.written) names += (names.empty() ? "" : ", ") + p.filename().string();
  logInfo("wrote " + names + " beside " + route_json.filename().string());
  return res.note;
}

}  // namespace slamroute::cli
