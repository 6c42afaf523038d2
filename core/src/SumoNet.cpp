// Reader for SUMO .net.xml(.gz) files (pugixml): junctions, edges, lanes, connections, location.
#include "slamroute/core/SumoNet.hpp"

#include <pugixml.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "slamroute/core/AtomicFile.hpp"
#include "slamroute/core/Coordinates.hpp"

namespace slamroute {
namespace {

std::vector<std::string> splitWords(const char* s) {
  std::vector<std::string> out;
  std::istringstream in(s ? s : "");
  std::string w;
  while (in >> w) out.push_back(w);
  return out;
}

/// A straight lane piece longer than this is no road; the world covers each piece's bounding box
/// with grid cells, so one such piece would take hours to build.
constexpr double kMaxShapeSegmentM = 50'000.0;

/// "x,y x,y,z …" (SUMO mixes 2D and 3D points); z defaults to 0.
Polyline parseShape(const char* s, const std::string& where) {
  Polyline pl;
  for (const auto& tok : splitWords(s)) {
    double v[3] = {0.0, 0.0, 0.0};
    int n = 0;
    std::size_t start = 0;
    while (start <= tok.size() && n < 3) {
      const std::size_t comma = tok.find(',', start);
      const std::string part =
          tok.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
      try {
        std::size_t used = 0;
        v[n++] = std::stod(part, &used);
        if (used != part.size()) throw std::invalid_argument(part);
      } catch (const std::exception&) {
        throw std::invalid_argument(where + ": bad shape point '" + tok + "'");
      }
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
    if (n < 2 || !plausibleCoordinate(v[0]) || !plausibleCoordinate(v[1]) ||
        !plausibleCoordinate(v[2]))
      throw std::invalid_argument(where + ": bad shape point '" + tok + "' (" + kCoordinateRule +
                                  ")");
    pl.emplace_back(v[0], v[1], v[2]);
  }
  for (std::size_t i = 1; i < pl.size(); ++i)
    if ((pl[i] - pl[i - 1]).head<2>().norm() > kMaxShapeSegmentM)
      throw std::invalid_argument(where + ": shape segment of " +
                                  std::to_string((pl[i] - pl[i - 1]).norm() / 1000.0) +
                                  " km without a bend; not a road");
  return pl;
}

/// A lane's length or speed attribute: finite, >= 0 and within the coordinate range (NaN or a
/// negative length gives NaN costs downstream and routes that cannot be read back).
double laneNumber(const pugi::xml_node& lane, const char* attr, const std::string& where) {
  const double v = lane.attribute(attr).as_double();
  if (!std::isfinite(v) || v < 0.0 || v > kMaxCoordinateM)
    throw std::invalid_argument(where + ": lane '" + lane.attribute("id").as_string() + "' has " +
                                attr + " '" + lane.attribute(attr).as_string() +
                                "' (needs a finite number >= 0)");
  return v;
}

Point3 junctionPosition(const pugi::xml_node& j, const std::string& name) {
  const Point3 p(j.attribute("x").as_double(), j.attribute("y").as_double(),
                 j.attribute("z").as_double(0.0));
  if (!plausibleCoordinate(p.x()) || !plausibleCoordinate(p.y()) || !plausibleCoordinate(p.z()))
    throw std::invalid_argument(name + ": junction '" + j.attribute("id").as_string() + "' at (" +
                                j.attribute("x").as_string() + ", " + j.attribute("y").as_string() +
                                ") (" + kCoordinateRule + ")");
  return p;
}

}  // namespace

bool passengerAllowed(const std::vector<std::string>& allow,
                      const std::vector<std::string>& disallow) {
  auto has = [](const std::vector<std::string>& v, const char* c) {
    return std::find(v.begin(), v.end(), c) != v.end();
  };
  // SUMO semantics: `allow` (if given) lists the only classes permitted; else `disallow` lists
  // the excluded ones; "all" stands for every class. Unknown (newer) classes are simply ignored.
  if (!allow.empty()) return has(allow, "passenger") || has(allow, "all");
  if (!disallow.empty()) return !(has(disallow, "passenger") || has(disallow, "all"));
  return true;
}

bool SumoLane::allowsPassenger() const { return passengerAllowed(allow, disallow); }

bool SumoEdge::allowsPassenger() const {
  return std::any_of(lanes.begin(), lanes.end(),
                     [](const SumoLane& l) { return l.allowsPassenger(); });
}

double SumoEdge::length() const {
  if (lanes.empty()) return polylineLength(shape);
  double s = 0.0;
  for (const auto& l : lanes) s += l.length_m;
  return s / static_cast<double>(lanes.size());
}

double SumoEdge::speed() const {
  double s = 0.0;
  for (const auto& l : lanes) s = std::max(s, l.speed_mps);
  return s;
}

const SumoEdge* SumoNet::findEdge(const std::string& id) const {
  auto it = edge_index.find(id);
  return it == edge_index.end() ? nullptr : &edges[it->second];
}

const SumoJunction* SumoNet::findJunction(const std::string& id) const {
  auto it = junction_index.find(id);
  return it == junction_index.end() ? nullptr : &junctions[it->second];
}

bool SumoNet::turnAllowed(const std::string& from, const std::string& to) const {
  auto it = turns_.find(from);
  if (it == turns_.end()) return false;
  return std::find(it->second.begin(), it->second.end(), to) != it->second.end();
}

namespace {

SumoLocation readLocation(const pugi::xml_node& loc, const std::string& name) {
  SumoLocation location;
  const auto off = splitWords(loc.attribute("netOffset").as_string());
  if (!off.empty()) {
    const auto pl = parseShape(loc.attribute("netOffset").as_string(), name + " <location>");
    if (!pl.empty()) location.net_offset = pl.front().head<2>();
  }
  location.conv_boundary = loc.attribute("convBoundary").as_string();
  location.orig_boundary = loc.attribute("origBoundary").as_string();
  location.proj_parameter = loc.attribute("projParameter").as_string();
  return location;
}

SumoLane readLane(const pugi::xml_node& l, const std::string& where) {
  SumoLane lane;
  lane.id = l.attribute("id").as_string();
  lane.index = l.attribute("index").as_int();
  lane.length_m = laneNumber(l, "length", where);
  lane.speed_mps = laneNumber(l, "speed", where);
  lane.width_m = l.attribute("width").as_double(3.2);
  lane.allow = splitWords(l.attribute("allow").as_string());
  lane.disallow = splitWords(l.attribute("disallow").as_string());
  lane.shape = parseShape(l.attribute("shape").as_string(), where);
  return lane;
}

/// A normal edge with its lanes; nothing for an internal (junction) edge.
std::optional<SumoEdge> readEdge(const pugi::xml_node& e, const std::string& name) {
  SumoEdge edge;
  edge.id = e.attribute("id").as_string();
  edge.function = e.attribute("function").as_string();
  if (edge.isInternal() || (!edge.id.empty() && edge.id[0] == ':')) return std::nullopt;
  const std::string where = name + ": edge '" + edge.id + "'";
  edge.from = e.attribute("from").as_string();
  edge.to = e.attribute("to").as_string();
  edge.type = e.attribute("type").as_string();
  edge.name = e.attribute("name").as_string();
  edge.priority = e.attribute("priority").as_int(-1);
  for (auto l : e.children("lane")) edge.lanes.push_back(readLane(l, where));
  if (edge.lanes.empty()) throw std::invalid_argument(where + " has no lanes");
  // Always the centre lane's shape (where cars drive): netconvert writes an edge's own shape
  // attribute only for custom-shaped edges, and there it is the road's centreline, shared by
  // both directions.
  edge.shape = edge.lanes[edge.lanes.size() / 2].shape;
  return edge;
}

/// A junction; nothing for an internal one.
std::optional<SumoJunction> readJunction(const pugi::xml_node& j, const std::string& name) {
  SumoJunction jn;
  jn.type = j.attribute("type").as_string();
  if (jn.type == "internal") return std::nullopt;
  jn.id = j.attribute("id").as_string();
  jn.pos = junctionPosition(j, name);
  jn.inc_lanes = splitWords(j.attribute("incLanes").as_string());
  return jn;
}

/// Whether passenger cars may take a connection: both lanes and the connection allow them.
bool connectionAllowsPassenger(const pugi::xml_node& c, const SumoConnection& con,
                               const SumoEdge& from, const SumoEdge& to) {
  bool passenger = false;
  for (const auto& l : from.lanes)
    if (l.index == con.from_lane) passenger = l.allowsPassenger();
  for (const auto& l : to.lanes)
    if (l.index == con.to_lane) passenger = passenger && l.allowsPassenger();
  if (c.attribute("allow") || c.attribute("disallow"))
    passenger = passenger && passengerAllowed(splitWords(c.attribute("allow").as_string()),
                                              splitWords(c.attribute("disallow").as_string()));
  return passenger;
}

pugi::xml_node parseNet(pugi::xml_document& doc, const std::string& data, const std::string& name) {
  const pugi::xml_parse_result res = doc.load_buffer(data.data(), data.size());
  if (!res)
    throw std::invalid_argument(name + ": not valid XML (" + res.description() + " at byte " +
                                std::to_string(res.offset) + ")");
  const pugi::xml_node root = doc.child("net");
  if (!root) throw std::invalid_argument(name + ": not a SUMO network (no <net> root element)");
  return root;
}

}  // namespace

namespace {

/// Internal (junction) lanes: their lengths and, for a lane that continues on another internal
/// lane (an internal junction splits a turn), that lane.
struct InternalLanes {
  std::unordered_map<std::string, double> length_m;
  std::unordered_map<std::string, std::string> next;

  static InternalLanes read(const pugi::xml_node& root) {
    InternalLanes in;
    for (auto e : root.children("edge")) {
      const std::string id = e.attribute("id").as_string();
      if (std::string(e.attribute("function").as_string()) != "internal" &&
          (id.empty() || id[0] != ':'))
        continue;
      for (auto l : e.children("lane"))
        in.length_m[l.attribute("id").as_string()] = l.attribute("length").as_double(0.0);
    }
    for (auto c : root.children("connection")) {
      const std::string from = c.attribute("from").as_string(),
                        via = c.attribute("via").as_string();
      if (!from.empty() && from[0] == ':' && !via.empty())
        in.next[from + "_" + std::to_string(c.attribute("fromLane").as_int())] = via;
    }
    return in;
  }

  /// Length of the chain of internal lanes starting at `lane` (cycles cannot occur in a valid
  /// net; the chain is cut after as many steps as there are lanes).
  double chainLength(std::string lane) const {
    double total = 0.0;
    for (std::size_t k = 0; k <= length_m.size() && !lane.empty(); ++k) {
      const auto it = length_m.find(lane);
      if (it == length_m.end()) break;
      total += it->second;
      const auto nx = next.find(lane);
      lane = nx == next.end() ? std::string() : nx->second;
    }
    return total;
  }
};

}  // namespace

struct SumoNetBuilder {
  static void addTurn(SumoNet& net, const std::string& from, const std::string& to) {
    auto& v = net.turns_[from];
    if (std::find(v.begin(), v.end(), to) == v.end()) v.push_back(to);
  }

  /// The connections between normal edges; those passenger cars may take are the allowed turns.
  static void readConnections(SumoNet& net, const pugi::xml_node& root) {
    const InternalLanes internal = InternalLanes::read(root);
    for (auto c : root.children("connection")) {
      SumoConnection con;
      con.from = c.attribute("from").as_string();
      con.to = c.attribute("to").as_string();
      const SumoEdge* fe = net.findEdge(con.from);
      const SumoEdge* te = net.findEdge(con.to);
      if (!fe || !te) continue;  // internal-lane connections
      con.from_lane = c.attribute("fromLane").as_int();
      con.to_lane = c.attribute("toLane").as_int();
      con.dir = c.attribute("dir").as_string();
      con.via = c.attribute("via").as_string();
      con.via_length_m = internal.chainLength(con.via);
      if (connectionAllowsPassenger(c, con, *fe, *te)) addTurn(net, con.from, con.to);
      net.connections.push_back(std::move(con));
    }
  }
};

SumoNet SumoNet::read(const std::filesystem::path& path) {
  const std::string name = path.string();
  const std::string data = readMaybeGzip(path);
  pugi::xml_document doc;
  const pugi::xml_node root = parseNet(doc, data, name);
  SumoNet net;
  net.source = path;
  if (auto loc = root.child("location")) net.location = readLocation(loc, name);
  for (auto e : root.children("edge"))
    if (auto edge = readEdge(e, name)) {
      net.edge_index[edge->id] = net.edges.size();
      net.edges.push_back(std::move(*edge));
    }
  for (auto j : root.children("junction"))
    if (auto jn = readJunction(j, name)) {
      net.junction_index[jn->id] = net.junctions.size();
      net.junctions.push_back(std::move(*jn));
    }
  SumoNetBuilder::readConnections(net, root);
  for (auto r : root.children("roundabout"))
    net.roundabouts.push_back({splitWords(r.attribute("nodes").as_string()),
                               splitWords(r.attribute("edges").as_string())});
  if (net.edges.empty() && net.junctions.empty())
    throw std::invalid_argument(name + ": SUMO network has no edges and no junctions");
  return net;
}

}  // namespace slamroute
