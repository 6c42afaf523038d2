// GPX 1.1 / KML 2.2 / instruction tables of a route.
#include "slamroute/export/RouteFiles.hpp"

#include <cstdio>
#include <sstream>

namespace slamroute::exports {
namespace {

std::string fixed(double v, int prec) {
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.*f", prec, v);
  return buf;
}

/// 7 decimals of a degree: about 1 cm on the ground.
std::string latLonAttrs(const LonLat& p) {
  return "lat=\"" + fixed(p.lat_deg, 7) + "\" lon=\"" + fixed(p.lon_deg, 7) + "\"";
}

std::string kmlCoord(const LonLat& p) {
  return fixed(p.lon_deg, 7) + "," + fixed(p.lat_deg, 7) + ",0";
}

std::string stepDescription(const Instruction& in) {
  std::string d = "at " + fixed(in.at_m / 1000.0, 2) + " km, then " + fixed(in.drive_m, 0) +
                  " m on " + (in.street.empty() ? "edge " + in.sumo_edges.back() : in.street);
  if (in.revisit != Revisit::None) d += "; driven again: " + revisitReason(in.revisit);
  return d;
}

/// CSV field: quoted when it holds a comma, a quote or a line break.
std::string csvField(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

/// Markdown table cell: a '|' in a street name would end the cell.
std::string mdCell(const std::string& s) {
  std::string out;
  for (char c : s) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

std::string joined(const std::vector<std::string>& v, const char* sep) {
  std::string out;
  for (std::size_t i = 0; i < v.size(); ++i) out += (i ? sep : "") + v[i];
  return out;
}

}  // namespace

std::string xmlEscape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

GeoRoute geoRoute(const std::string& name, const std::string& description, const DrivenPath& path,
                  const std::vector<Instruction>& steps, const GeoProjection& proj) {
  GeoRoute g;
  g.name = name;
  g.description = description;
  for (const auto& p : path.points) g.track.push_back(proj.toLonLat(p.head<2>()));
  for (const auto& in : steps) {
    g.turn_points.push_back(proj.toLonLat(in.at_xy));
    g.turn_names.push_back(std::to_string(in.step) + ". " + instructionText(in));
    g.turn_descriptions.push_back(stepDescription(in));
  }
  return g;
}

std::string gpxText(const GeoRoute& r) {
  std::ostringstream o;
  o << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
    << "<gpx version=\"1.1\" creator=\"slamroute\" xmlns=\"http://www.topografix.com/GPX/1/1\" "
       "xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\" xsi:schemaLocation=\""
       "http://www.topografix.com/GPX/1/1 http://www.topografix.com/GPX/1/1/gpx.xsd\">\n"
    << "  <metadata>\n    <name>" << xmlEscape(r.name) << "</name>\n    <desc>"
    << xmlEscape(r.description) << "</desc>\n  </metadata>\n";
  o << "  <rte>\n    <name>" << xmlEscape(r.name) << "</name>\n";
  for (std::size_t i = 0; i < r.turn_points.size(); ++i)
    o << "    <rtept " << latLonAttrs(r.turn_points[i]) << ">\n      <name>"
      << xmlEscape(r.turn_names[i]) << "</name>\n      <desc>" << xmlEscape(r.turn_descriptions[i])
      << "</desc>\n    </rtept>\n";
  o << "  </rte>\n  <trk>\n    <name>" << xmlEscape(r.name) << "</name>\n    <trkseg>\n";
  for (const auto& p : r.track) o << "      <trkpt " << latLonAttrs(p) << "/>\n";
  o << "    </trkseg>\n  </trk>\n</gpx>\n";
  return o.str();
}

std::string kmlText(const GeoRoute& r) {
  std::ostringstream o;
  o << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
    << "<kml xmlns=\"http://www.opengis.net/kml/2.2\">\n<Document>\n  <name>" << xmlEscape(r.name)
    << "</name>\n  <description>" << xmlEscape(r.description) << "</description>\n"
    << "  <Style id=\"drive\"><LineStyle><color>ff2020e0</color><width>4</width></LineStyle>"
       "</Style>\n"
    << "  <Placemark>\n    <name>" << xmlEscape(r.name) << "</name>\n    <styleUrl>#drive"
    << "</styleUrl>\n    <LineString>\n      <tessellate>1</tessellate>\n      <coordinates>\n";
  for (const auto& p : r.track) o << "        " << kmlCoord(p) << "\n";
  o << "      </coordinates>\n    </LineString>\n  </Placemark>\n  <Folder>\n    <name>Turns"
    << "</name>\n";
  for (std::size_t i = 0; i < r.turn_points.size(); ++i)
    o << "    <Placemark>\n      <name>" << xmlEscape(r.turn_names[i]) << "</name>\n"
      << "      <description>" << xmlEscape(r.turn_descriptions[i]) << "</description>\n"
      << "      <Point><coordinates>" << kmlCoord(r.turn_points[i])
      << "</coordinates></Point>\n    </Placemark>\n";
  o << "  </Folder>\n</Document>\n</kml>\n";
  return o.str();
}

std::string instructionsMarkdown(const std::string& title, const std::vector<Instruction>& steps,
                                 double route_length_m, const GeoProjection* proj) {
  std::ostringstream o;
  o << "# " << title << "\n\n"
    << steps.size() << " steps, " << fixed(route_length_m / 1000.0, 2)
    << " km. \"Driven again\" says why the route comes back onto a street it drove before.\n\n"
    << "| step | at [km] | instruction | then drive [m] | driven again |"
    << (proj ? " lat, lon |" : "") << "\n|---|---|---|---|---|" << (proj ? "---|" : "") << "\n";
  for (const auto& in : steps) {
    std::string again = revisitReason(in.revisit);
    if (!in.revisit_detail.empty()) again += " (" + in.revisit_detail + ")";
    o << "| " << in.step << " | " << fixed(in.at_m / 1000.0, 2) << " | "
      << mdCell(instructionText(in)) << " | " << fixed(in.drive_m, 0) << " | " << again << " |";
    if (proj) {
      const LonLat ll = proj->toLonLat(in.at_xy);
      o << " " << fixed(ll.lat_deg, 6) << ", " << fixed(ll.lon_deg, 6) << " |";
    }
    o << "\n";
  }
  return o.str();
}

std::string instructionsCsv(const std::vector<Instruction>& steps, const GeoProjection* proj) {
  std::ostringstream o;
  o << "step,at_m,manoeuvre,roundabout_exit,street,drive_m,sumo_edges,driven_again,why,detail,"
       "x_m,y_m,lon_deg,lat_deg\n";
  for (const auto& in : steps) {
    o << in.step << "," << fixed(in.at_m, 1) << "," << csvField(manoeuvreName(in.manoeuvre)) << ","
      << in.roundabout_exit << "," << csvField(in.street) << "," << fixed(in.drive_m, 1) << ","
      << csvField(joined(in.sumo_edges, " ")) << "," << (in.revisit != Revisit::None ? 1 : 0) << ","
      << csvField(revisitReason(in.revisit)) << "," << csvField(in.revisit_detail) << ","
      << fixed(in.at_xy.x(), 2) << "," << fixed(in.at_xy.y(), 2) << ",";
    if (proj) {
      const LonLat ll = proj->toLonLat(in.at_xy);
      o << fixed(ll.lon_deg, 7) << "," << fixed(ll.lat_deg, 7);
    } else {
      o << ",";
    }
    o << "\n";
  }
  return o.str();
}

}  // namespace slamroute::exports
