#include "HtmlLayers.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "slamroute/core/AtomicFile.hpp"

namespace slamroute::cli {
using nlohmann::json;

namespace {

/// `bytes` as base64 (RFC 4648), for a data: URI.
std::string base64(const std::string& bytes) {
  static const char* abc = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned v = (static_cast<unsigned char>(bytes[i]) << 16) |
                       (static_cast<unsigned char>(bytes[i + 1]) << 8) |
                       static_cast<unsigned char>(bytes[i + 2]);
    for (int k = 18; k >= 0; k -= 6) out += abc[(v >> k) & 63];
  }
  if (const std::size_t rest = bytes.size() - i; rest > 0) {
    unsigned v = static_cast<unsigned char>(bytes[i]) << 16;
    if (rest == 2) v |= static_cast<unsigned char>(bytes[i + 1]) << 8;
    out += abc[(v >> 18) & 63];
    out += abc[(v >> 12) & 63];
    out += rest == 2 ? abc[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

}  // namespace

double htmlRounded(double v, double unit) { return std::round(v / unit) * unit; }

json MapFrame::at(const Point2& p) const {
  if (!proj) return json::array({htmlRounded(p.y(), 0.01), htmlRounded(p.x(), 0.01)});
  const exports::LonLat ll = proj->toLonLat(p);
  return json::array({htmlRounded(ll.lat_deg, 1e-7), htmlRounded(ll.lon_deg, 1e-7)});
}

json MapFrame::line(const Polyline& pl) const {
  json out = json::array();
  for (const auto& p : pl) out.push_back(at(p.head<2>()));
  return out;
}

json routeLayer(const SumoNet& net, const Route& r, const MapFrame& f) {
  std::map<std::string, int> times;
  for (const auto& id : r.sumo_edges) ++times[id];
  json out = json::array();
  for (const auto& id : r.sumo_edges) {
    const SumoEdge* e = net.findEdge(id);
    out.push_back({{"edge", id},
                   {"name", e ? e->name : ""},
                   {"n", times[id]},
                   {"pts", e ? f.line(e->shape) : json::array()}});
  }
  return out;
}

json driveLayer(const std::vector<evaluate::PosePair>& pairs, const Pose3& T_gt_est,
                const std::vector<double>& distance_m, const std::vector<double>& errors_m,
                const MapFrame& f) {
  constexpr std::size_t kMaxPoints = 2000;
  const std::size_t step = std::max<std::size_t>(1, (pairs.size() + kMaxPoints - 1) / kMaxPoints);
  json gt = json::array(), est = json::array(), d = json::array(), err = json::array(),
       t = json::array();
  for (std::size_t i = 0; i < pairs.size(); i += step) {
    const auto& p = pairs[i];
    gt.push_back(f.at(p.gt.translation().head<2>()));
    est.push_back(f.at((T_gt_est * p.est).translation().head<2>()));
    d.push_back(htmlRounded(distance_m[i], 0.1));
    err.push_back(htmlRounded(errors_m[i], 1e-3));
    t.push_back(htmlRounded(p.t, 0.01));
  }
  return {{"gt", gt}, {"est", est}, {"d", d}, {"err", err}, {"t", t}};
}

std::string pngDataUri(const std::filesystem::path& png) {
  return "data:image/png;base64," + base64(readFile(png));
}

}  // namespace slamroute::cli
