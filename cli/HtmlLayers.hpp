#pragma once
// Map data of report.html shared by its parts (HtmlReport.cpp, HtmlFleet.cpp): the map frame
// (globe or the net's metres), a route as one feature per SUMO edge driven and a drive's
// trajectories.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "slamroute/core/Route.hpp"
#include "slamroute/core/SumoNet.hpp"
#include "slamroute/evaluate/Metrics.hpp"
#include "slamroute/export/GeoProjection.hpp"

namespace slamroute::cli {

/// `v` rounded to a multiple of `unit` (keeps the page small).
double htmlRounded(double v, double unit);

/// Map coordinates: [lat, lon] on the globe, else [y, x] in metres (Leaflet's plain CRS).
struct MapFrame {
  std::optional<exports::GeoProjection> proj;
  nlohmann::json at(const Point2& p) const;
  nlohmann::json line(const Polyline& pl) const;
};

/// One feature per SUMO edge of the route, in driving order, with how often the route drives it.
nlohmann::json routeLayer(const SumoNet& net, const Route& r, const MapFrame& f);

/// A drive for the page's slider: the ground truth and the estimate after `T_gt_est` ("gt",
/// "est"), the error ("err"), the distance along the ground truth ("d") and the time ("t") per
/// associated pose, thinned to at most 2000 poses (enough for the slider, a small file).
nlohmann::json driveLayer(const std::vector<evaluate::PosePair>& pairs, const Pose3& T_gt_est,
                          const std::vector<double>& distance_m,
                          const std::vector<double>& errors_m, const MapFrame& f);

/// The PNG at `png` as a data: URI (base64), for an <img> inside the page.
std::string pngDataUri(const std::filesystem::path& png);

}  // namespace slamroute::cli
