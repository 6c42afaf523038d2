// Readers for location traces: traces.csv and SUMO FCD XML.
#include "slamroute/roadgraph/Traces.hpp"

#include <pugixml.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <tuple>
#include <unordered_map>

#include "slamroute/core/AtomicFile.hpp"
#include "slamroute/core/Coordinates.hpp"

namespace slamroute::roadgraph {
namespace {

std::vector<std::string> splitCsv(const std::string& line) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : line) {
    if (c == ',') {
      out.push_back(cur);
      cur.clear();
    } else if (c != '\r' && c != '"') {
      cur.push_back(c);
    }
  }
  out.push_back(cur);
  return out;
}

double parseNumber(const std::string& s, const std::string& where) {
  try {
    std::size_t used = 0;
    const double v = std::stod(s, &used);
    if (used != s.size() && s.find_first_not_of(" \t", used) != std::string::npos)
      throw std::invalid_argument("trailing text");
    return v;
  } catch (const std::exception&) {
    // "nan"/"inf" are parsed by stod; anything else unparsable lands here.
    throw std::invalid_argument(where + ": not a number: '" + s + "'");
  }
}

int vehicleIndex(Traces& tr, std::unordered_map<std::string, int>& ids, const std::string& name) {
  const auto it = ids.find(name);
  if (it != ids.end()) return it->second;
  const int id = static_cast<int>(tr.vehicles.size());
  tr.vehicles.push_back(name);
  ids.emplace(name, id);
  return id;
}

/// Vehicles numbered by name and points sorted by (vehicle, time, position, heading, speed): the
/// graph then depends on the rows' content only, not on the order a file lists them in.
void canonicalOrder(Traces& tr) {
  std::vector<int> by_name(tr.vehicles.size());
  std::iota(by_name.begin(), by_name.end(), 0);
  std::sort(by_name.begin(), by_name.end(), [&](int a, int b) {
    return tr.vehicles[static_cast<std::size_t>(a)] < tr.vehicles[static_cast<std::size_t>(b)];
  });
  std::vector<int> new_id(tr.vehicles.size());
  std::vector<std::string> names(tr.vehicles.size());
  for (std::size_t k = 0; k < by_name.size(); ++k) {
    new_id[static_cast<std::size_t>(by_name[k])] = static_cast<int>(k);
    names[k] = tr.vehicles[static_cast<std::size_t>(by_name[k])];
  }
  tr.vehicles = std::move(names);
  for (auto& p : tr.points) p.vehicle = new_id[static_cast<std::size_t>(p.vehicle)];
  auto key = [](const TracePoint& p) {
    return std::make_tuple(p.vehicle, p.t, p.pos.x(), p.pos.y(), p.pos.z(), p.heading_deg, p.speed);
  };
  std::stable_sort(tr.points.begin(), tr.points.end(),
                   [&](const TracePoint& a, const TracePoint& b) { return key(a) < key(b); });
}

}  // namespace

Traces readTracesCsv(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path.string() + ": cannot open traces file");
  Traces tr;
  tr.source = path.string();
  std::string line;
  if (!std::getline(in, line)) throw std::invalid_argument(tr.source + ": empty traces file");
  const auto header = splitCsv(line);
  auto col = [&](const std::string& name, bool required) {
    for (std::size_t i = 0; i < header.size(); ++i)
      if (header[i] == name) return static_cast<int>(i);
    if (required)
      throw std::invalid_argument(tr.source + ": missing column '" + name +
                                  "' (expected t,vehicle,x,y,z,heading_deg,speed)");
    return -1;
  };
  const int ct = col("t", true), cv = col("vehicle", true), cx = col("x", true),
            cy = col("y", true), cz = col("z", false), ch = col("heading_deg", false),
            cs = col("speed", false);
  std::unordered_map<std::string, int> ids;
  std::size_t lineno = 1;
  while (std::getline(in, line)) {
    ++lineno;
    if (line.empty() || line == "\r") continue;
    const auto f = splitCsv(line);
    const std::string where = tr.source + ":" + std::to_string(lineno);
    if (f.size() < header.size())
      throw std::invalid_argument(where + ": expected " + std::to_string(header.size()) +
                                  " columns, got " + std::to_string(f.size()));
    TracePoint p;
    p.t = parseNumber(f[static_cast<std::size_t>(ct)], where);
    p.vehicle = vehicleIndex(tr, ids, f[static_cast<std::size_t>(cv)]);
    p.pos.x() = parseNumber(f[static_cast<std::size_t>(cx)], where);
    p.pos.y() = parseNumber(f[static_cast<std::size_t>(cy)], where);
    p.pos.z() = cz >= 0 ? parseNumber(f[static_cast<std::size_t>(cz)], where) : 0.0;
    p.heading_deg = ch >= 0 ? parseNumber(f[static_cast<std::size_t>(ch)], where) : 0.0;
    p.speed = cs >= 0 ? parseNumber(f[static_cast<std::size_t>(cs)], where) : 0.0;
    tr.points.push_back(p);
  }
  canonicalOrder(tr);
  return tr;
}

Traces readFcdXml(const std::filesystem::path& path) {
  const std::string text = readMaybeGzip(path);
  pugi::xml_document doc;
  const auto res = doc.load_buffer(text.data(), text.size());
  if (!res)
    throw std::invalid_argument(path.string() + ": not valid XML (" + res.description() + ")");
  const auto root = doc.child("fcd-export");
  if (!root) throw std::invalid_argument(path.string() + ": not a SUMO FCD file (no <fcd-export>)");
  Traces tr;
  tr.source = path.string();
  std::unordered_map<std::string, int> ids;
  for (const auto ts : root.children("timestep")) {
    const double t = ts.attribute("time").as_double(NAN);
    for (const auto v : ts.children("vehicle")) {
      TracePoint p;
      p.t = t;
      p.vehicle = vehicleIndex(tr, ids, v.attribute("id").as_string());
      p.pos = Point3(v.attribute("x").as_double(NAN), v.attribute("y").as_double(NAN),
                     v.attribute("z").as_double(0.0));
      // SUMO navigation angle: 0 = north, clockwise -> mathematical heading: 0 = east, ccw.
      p.heading_deg = 90.0 - v.attribute("angle").as_double(0.0);
      p.speed = v.attribute("speed").as_double(0.0);
      tr.points.push_back(p);
    }
  }
  canonicalOrder(tr);
  return tr;
}

Traces readTraces(const std::filesystem::path& path) {
  if (!std::filesystem::exists(path))
    throw std::runtime_error(path.string() + ": traces file not found");
  std::ifstream in(path, std::ios::binary);
  char head[2] = {0, 0};
  in.read(head, 2);
  const bool gz =
      static_cast<unsigned char>(head[0]) == 0x1f && static_cast<unsigned char>(head[1]) == 0x8b;
  std::string first;
  in.seekg(0);
  std::getline(in, first);
  const auto ext = path.extension().string();
  if (gz || ext == ".xml" || first.find('<') != std::string::npos) return readFcdXml(path);
  return readTracesCsv(path);
}

std::vector<std::size_t> byVehicleThenTime(const Traces& traces) {
  const auto& P = traces.points;
  std::vector<std::size_t> order(P.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return P[a].vehicle != P[b].vehicle ? P[a].vehicle < P[b].vehicle : P[a].t < P[b].t;
  });
  return order;
}

void checkTraces(const Traces& tr, const std::string& where) {
  if (tr.points.empty()) throw std::invalid_argument(where + ": traces are empty (no points)");
  if (tr.points.size() < 2)
    throw std::invalid_argument(where + ": traces hold a single point; need a driven trace");
  for (std::size_t i = 0; i < tr.points.size(); ++i) {
    const auto& p = tr.points[i];
    if (!std::isfinite(p.t) || !p.pos.allFinite())
      throw std::invalid_argument(where + ": point " + std::to_string(i) + " (vehicle '" +
                                  tr.vehicles.at(static_cast<std::size_t>(p.vehicle)) +
                                  "') has a NaN or infinite time/coordinate");
    if (!plausibleCoordinate(p.pos.x()) || !plausibleCoordinate(p.pos.y()) ||
        !plausibleCoordinate(p.pos.z()))
      throw std::invalid_argument(where + ": point " + std::to_string(i) + " (vehicle '" +
                                  tr.vehicles.at(static_cast<std::size_t>(p.vehicle)) +
                                  "'): " + kCoordinateRule);
  }
}

}  // namespace slamroute::roadgraph
