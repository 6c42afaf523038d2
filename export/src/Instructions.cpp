// Turn-by-turn instructions: group a route's SUMO edges into steps (a manoeuvre, then driving
// on one street) and say why a street is driven again.
#include "slamroute/export/Instructions.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <unordered_map>
#include <unordered_set>

namespace slamroute::exports {
namespace {

struct EdgeOnRoute {
  const SumoEdge* e = nullptr;
  double start_m = 0.0, len_m = 0.0;
  bool roundabout = false;
  bool driven_before = false;      ///< this edge or its opposite direction came earlier
  double since_last_visit_m = -1;  ///< driving since the route was last at e->from (-1: never)
  bool new_street_later = false;   ///< an edge not driven before comes at or after this one
};

/// Per route edge: position along the route and what was driven before it.
std::vector<EdgeOnRoute> edgesOnRoute(const SumoNet& net, const std::vector<std::string>& ids) {
  std::unordered_set<std::string> ring;
  for (const auto& r : net.roundabouts) ring.insert(r.edges.begin(), r.edges.end());
  std::vector<EdgeOnRoute> out;
  std::unordered_set<std::string> driven;  // "from>to" of every edge driven, both directions
  std::unordered_map<std::string, double> last_at;  // junction -> distance of the last visit
  double dist = 0.0;
  for (const auto& id : ids) {
    EdgeOnRoute s;
    s.e = net.findEdge(id);
    if (!s.e)
      throw std::invalid_argument(net.source.string() + ": the route's SUMO edge '" + id +
                                  "' is not in this net");
    s.start_m = dist;
    s.len_m = polylineLength(s.e->shape);
    s.roundabout = ring.count(id) > 0;
    s.driven_before = driven.count(s.e->from + ">" + s.e->to) > 0;
    if (out.empty())
      last_at[s.e->from] = 0.0;
    else if (auto it = last_at.find(s.e->from); it != last_at.end() && it->second < dist)
      s.since_last_visit_m = dist - it->second;
    driven.insert(s.e->from + ">" + s.e->to);
    driven.insert(s.e->to + ">" + s.e->from);
    if (!out.empty()) last_at[s.e->from] = dist;
    dist += s.len_m;
    out.push_back(s);
  }
  bool later = false;
  for (auto it = out.rbegin(); it != out.rend(); ++it) {
    later = later || !it->driven_before;
    it->new_street_later = later;
  }
  return out;
}

double headingDeg(const Point3& a, const Point3& b) {
  return std::atan2(b.y() - a.y(), b.x() - a.x()) * 180.0 / std::numbers::pi;
}

/// The turn from the end of `a` onto the start of `b` by their shapes' headings (used where
/// the net has no <connection> for it).
Manoeuvre manoeuvreByAngle(const SumoEdge& a, const SumoEdge& b) {
  if (a.shape.size() < 2 || b.shape.size() < 2) return Manoeuvre::Straight;
  double d =
      headingDeg(b.shape[0], b.shape[1]) - headingDeg(a.shape[a.shape.size() - 2], a.shape.back());
  while (d > 180.0) d -= 360.0;
  while (d <= -180.0) d += 360.0;
  const double m = std::abs(d);
  if (m < 20.0) return Manoeuvre::Straight;
  if (m > 150.0) return Manoeuvre::UTurn;
  if (m < 45.0) return d > 0 ? Manoeuvre::SlightLeft : Manoeuvre::SlightRight;
  return d > 0 ? Manoeuvre::Left : Manoeuvre::Right;
}

Manoeuvre manoeuvreOf(const SumoNet& net, const SumoEdge& a, const SumoEdge& b) {
  for (const auto& c : net.connections) {
    if (c.from != a.id || c.to != b.id) continue;
    if (c.dir == "s") return Manoeuvre::Straight;
    if (c.dir == "l") return Manoeuvre::Left;
    if (c.dir == "r") return Manoeuvre::Right;
    if (c.dir == "L") return Manoeuvre::SlightLeft;
    if (c.dir == "R") return Manoeuvre::SlightRight;
    if (c.dir == "t") return Manoeuvre::UTurn;
  }
  return manoeuvreByAngle(a, b);
}

/// Exits passed from entering the roundabout at route edge `i` up to leaving it; sets `leave`
/// to the first route edge after the ring (ids.size() when the route ends on it).
int roundaboutExit(const SumoNet& net, const std::vector<EdgeOnRoute>& r, std::size_t i,
                   std::size_t& leave) {
  std::unordered_set<std::string> ring;
  for (const auto& rb : net.roundabouts) ring.insert(rb.edges.begin(), rb.edges.end());
  std::unordered_map<std::string, bool> has_exit;  // junction -> a road leaves the ring there
  for (const auto& e : net.edges)
    if (!ring.count(e.id) && e.allowsPassenger()) has_exit[e.from] = true;
  int exits = 0;
  for (leave = i; leave < r.size() && r[leave].roundabout; ++leave)
    if (has_exit.count(r[leave].e->to)) ++exits;
  return leave < r.size() ? exits : 0;
}

Revisit revisitOf(const EdgeOnRoute& s, const InstructionConfig& cfg, std::string& detail) {
  if (!s.driven_before) return Revisit::None;
  if (s.since_last_visit_m >= cfg.loop_min_travel_m) {
    detail = "back at junction " + s.e->from + " after " +
             std::to_string(static_cast<long>(std::lround(s.since_last_visit_m))) + " m";
    return Revisit::LoopClosure;
  }
  if (!s.new_street_later) {
    detail = "no street after it is new";
    return Revisit::Return;
  }
  detail = "on the way to streets not yet driven";
  return Revisit::Connection;
}

Point2 manoeuvrePoint(const SumoNet& net, const SumoEdge& e, bool depart) {
  const SumoJunction* j = net.findJunction(e.from);
  if (depart || !j) return e.shape.empty() ? Point2::Zero() : Point2(e.shape[0].head<2>());
  return j->pos.head<2>();
}

/// Edge `k` continues the current step: straight on, on the same named street, revisited or not
/// like the step's edges so far.
bool continuesStep(const SumoNet& net, const std::vector<EdgeOnRoute>& r, std::size_t k) {
  const EdgeOnRoute &a = r[k - 1], &b = r[k];
  if (b.roundabout && !a.roundabout) return false;
  if (b.e->name.empty() || b.e->name != a.e->name) return false;
  if (b.driven_before != a.driven_before) return false;
  return manoeuvreOf(net, *a.e, *b.e) == Manoeuvre::Straight;
}

}  // namespace

std::string manoeuvreName(Manoeuvre m) {
  switch (m) {
    case Manoeuvre::Depart:
      return "depart";
    case Manoeuvre::Straight:
      return "straight";
    case Manoeuvre::SlightLeft:
      return "slight left";
    case Manoeuvre::Left:
      return "left";
    case Manoeuvre::SlightRight:
      return "slight right";
    case Manoeuvre::Right:
      return "right";
    case Manoeuvre::UTurn:
      return "U-turn";
    case Manoeuvre::Roundabout:
      return "roundabout";
  }
  return "?";
}

std::string revisitReason(Revisit r) {
  switch (r) {
    case Revisit::None:
      return "";
    case Revisit::LoopClosure:
      return "loop-closure revisit";
    case Revisit::Connection:
      return "coverage connection";
    case Revisit::Return:
      return "return";
  }
  return "?";
}

std::vector<Instruction> turnByTurn(const SumoNet& net, const std::vector<std::string>& sumo_edges,
                                    const InstructionConfig& cfg) {
  const std::vector<EdgeOnRoute> r = edgesOnRoute(net, sumo_edges);
  std::vector<Instruction> steps;
  for (std::size_t k = 0; k < r.size();) {
    Instruction in;
    in.step = static_cast<int>(steps.size()) + 1;
    in.at_m = r[k].start_m;
    in.at_xy = manoeuvrePoint(net, *r[k].e, k == 0);
    std::size_t end = k + 1;  // one past the step's last edge
    if (k == 0) {
      in.manoeuvre = Manoeuvre::Depart;
    } else if (r[k].roundabout && !r[k - 1].roundabout) {
      in.manoeuvre = Manoeuvre::Roundabout;
      in.roundabout_exit = roundaboutExit(net, r, k, end);
      end = std::min(end + 1, r.size());
    } else {
      in.manoeuvre = manoeuvreOf(net, *r[k - 1].e, *r[k].e);
    }
    while (end < r.size() && continuesStep(net, r, end)) ++end;
    const EdgeOnRoute& named = r[end - 1];
    in.street = named.e->name;
    for (std::size_t m = k; m < end; ++m) {
      in.sumo_edges.push_back(r[m].e->id);
      in.drive_m += r[m].len_m;
      if (in.revisit == Revisit::None) in.revisit = revisitOf(r[m], cfg, in.revisit_detail);
    }
    steps.push_back(std::move(in));
    k = end;
  }
  return steps;
}

std::string instructionText(const Instruction& in) {
  const std::string street = in.street.empty() ? "edge " + in.sumo_edges.back() : in.street;
  switch (in.manoeuvre) {
    case Manoeuvre::Depart:
      return "Depart on " + street;
    case Manoeuvre::Straight:
      return "Continue straight onto " + street;
    case Manoeuvre::UTurn:
      return "Make a U-turn onto " + street;
    case Manoeuvre::Roundabout:
      return in.roundabout_exit > 0 ? "At the roundabout take exit " +
                                          std::to_string(in.roundabout_exit) + " onto " + street
                                    : "Enter the roundabout";
    default:
      return "Turn " + manoeuvreName(in.manoeuvre) + " onto " + street;
  }
}

}  // namespace slamroute::exports
