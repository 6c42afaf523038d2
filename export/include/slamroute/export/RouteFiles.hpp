#pragma once
// Text of the crew's route files: GPX 1.1, KML 2.2 and the turn-by-turn instructions (Markdown,
// CSV). Pure functions of their inputs (no clock, no host): same route, same bytes.
#include <optional>
#include <string>
#include <vector>

#include "slamroute/export/DrivenPath.hpp"
#include "slamroute/export/GeoProjection.hpp"
#include "slamroute/export/Instructions.hpp"

namespace slamroute::exports {

/// A route on the globe: the driven polyline and a point per instruction.
struct GeoRoute {
  std::string name;                            ///< e.g. "qlearning route"
  std::string description;                     ///< one line: length, edges, source net
  std::vector<LonLat> track;                   ///< the driven polyline
  std::vector<LonLat> turn_points;             ///< one per instruction
  std::vector<std::string> turn_names;         ///< instructionText of each
  std::vector<std::string> turn_descriptions;  ///< distance, street, revisit reason
};

GeoRoute geoRoute(const std::string& name, const std::string& description, const DrivenPath& path,
                  const std::vector<Instruction>& steps, const GeoProjection& proj);

/// GPX 1.1: <rte> with a <rtept> at every instruction, <trk> with the driven polyline.
std::string gpxText(const GeoRoute& r);
/// KML 2.2: the driven polyline as a LineString and a folder of turn points.
std::string kmlText(const GeoRoute& r);

/// Markdown table of the steps; with `proj`, each step's longitude / latitude too.
std::string instructionsMarkdown(const std::string& title, const std::vector<Instruction>& steps,
                                 double route_length_m, const GeoProjection* proj);
/// CSV: step,at_m,manoeuvre,roundabout_exit,street,drive_m,sumo_edges,driven_again,why,detail,
/// x_m,y_m,lon_deg,lat_deg (lon/lat empty without `proj`).
std::string instructionsCsv(const std::vector<Instruction>& steps, const GeoProjection* proj);

/// `s` with & < > " ' as XML entities.
std::string xmlEscape(const std::string& s);

}  // namespace slamroute::exports
