// Drives from junction to junction (paper §3.1 step 2, cases the paper leaves open).
//
// - Short links. Removing "node points and their neighbourhood" (clear_radius_m around every
//   node) also removes every street shorter than about twice that radius: two junctions 15-28 m
//   apart end up with no street points between them and no edge, although vehicles drive from
//   one to the other (Bologna: 9 such pairs, several on the only way out of a part of the
//   network). Drives between two junctions with no street point in between give that link.
//   Where a street already joins the two, a link is added for a direction no vehicle drove along
//   it: at a junction complex the street can be one carriageway (Bologna junction 15: the
//   eastbound lane between two nodes 22 m apart is a street of its own, while the westbound
//   traffic turns through the junction box, past no street point). A drive from a node along a
//   street whose near end it did not pass (a node of the same junction complex, 15-30 m off:
//   Bologna junction 3, whose arms end at two nodes 21 m apart) is a drive from that node to the
//   street's near end, past no street point, and counts for a link between the two; so is a
//   drive along a street to a node past the street's far end.
// - Short streets. Of a street 25-40 m long only a few metres are left outside the cleared
//   disks, too little for a run to show its direction of travel: drives from one end node to the
//   other over that street's points give it (otherwise a two-way street can look one-way).
//
// Choices (EdgeConfig):
// - A vehicle passes through a junction when it comes within link_visit_m (12 m, the cleared
//   radius) of its node: the node of a big junction lies up to 10-15 m from lanes through it.
// - A drive that passes the points of two streets between its junctions is no drive along either.
// - Links join nodes at most link_max_m apart (farther apart a street is left between them unless
//   it is a dropped fragment; the cap keeps a drive through a chain of close junctions from
//   linking its first and last) and need min_link_vehicles different vehicles per direction: one
//   car cutting a corner through two junction boxes or GPS noise at the border between two
//   neighbourhoods is not a street.
#include "ShortLinks.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "Streets.hpp"

namespace slamroute::roadgraph::detail {

Passages junctionPassages(const Traces& traces, const std::vector<std::size_t>& order,
                          const std::vector<int>& street_of_point, const std::vector<Point3>& nodes,
                          std::size_t n_inter, const EdgeConfig& ec, double half_height_m) {
  const auto& P = traces.points;
  auto nearest = [&](std::size_t i) {  // nearest intersection node within link_visit_m, or -1
    int best = -1;
    double bd = ec.link_visit_m;
    for (std::size_t j = 0; j < n_inter; ++j) {
      if (std::abs(nodes[j].z() - P[i].pos.z()) > half_height_m) continue;
      const double d = (nodes[j] - P[i].pos).head<2>().norm();
      if (d <= bd) {
        bd = d;
        best = static_cast<int>(j);
      }
    }
    return best;
  };
  std::map<std::tuple<int, int, int>, std::set<int>> drivers;
  int last = -1;         // junction passed last, -1 = none
  int between = -1;      // street whose points the vehicle passed since, -1 = none
  bool several = false;  // ... points of more than one street
  for (std::size_t k = 0; k < order.size(); ++k) {
    const std::size_t i = order[k];
    if (k > 0) {
      const auto& q = P[order[k - 1]];
      if (q.vehicle != P[i].vehicle || P[i].t - q.t > ec.max_gap_s) last = -1;
    }
    const int s = street_of_point[i];
    if (s >= 0) {
      if (between >= 0 && between != s) several = true;
      between = s;
      continue;
    }
    const int here = nearest(i);
    if (here < 0) continue;
    if (here != last && last >= 0 && !several) drivers[{last, here, between}].insert(P[i].vehicle);
    last = here;
    between = -1;
    several = false;
  }
  Passages out;
  for (const auto& [key, vehicles] : drivers) out[key] = static_cast<int>(vehicles.size());
  return out;
}

namespace {

/// Directions (from, to) between two nodes that some vehicle drove along a street joining them.
std::set<std::pair<int, int>> drivenAlongStreets(const Passages& passages,
                                                 const std::vector<Street>& streets) {
  std::set<std::pair<int, int>> out;
  for (const auto& [key, vehicles] : passages) {
    const auto [from, to, street] = key;
    if (street < 0 || vehicles < 1) continue;
    const Street& s = streets[static_cast<std::size_t>(street)];
    if ((s.u == from && s.v == to) || (s.u == to && s.v == from)) out.emplace(from, to);
  }
  return out;
}

/// Vehicles per direction (from, to) that drove from one node to the other past no street point:
/// drives with no street between, and drives that entered a street at an end they did not pass
/// (from -> that end) or left it at one (that end -> to).
std::map<std::pair<int, int>, int> linkDrives(const Passages& passages,
                                              const std::vector<Street>& streets) {
  std::map<std::pair<int, int>, int> out;
  for (const auto& [key, vehicles] : passages) {
    const auto [from, to, street] = key;
    if (street < 0) {
      out[{from, to}] += vehicles;
      continue;
    }
    const Street& s = streets[static_cast<std::size_t>(street)];
    const bool from_end = from == s.u || from == s.v, to_end = to == s.u || to == s.v;
    if (!from_end && to_end) out[{from, to == s.u ? s.v : s.u}] += vehicles;
    if (from_end && !to_end) out[{from == s.u ? s.v : s.u, to}] += vehicles;
  }
  return out;
}

}  // namespace

void addShortLinks(const Passages& passages, const std::vector<Point3>& nodes, const EdgeConfig& ec,
                   std::vector<Street>& streets, std::vector<Polyline>& polys,
                   GraphBuildStats& st) {
  if (!(ec.link_max_m > 0)) return;
  const std::set<std::pair<int, int>> along = drivenAlongStreets(passages, streets);
  std::map<std::pair<int, int>, Street> links;
  for (const auto& [key, vehicles] : linkDrives(passages, streets)) {
    const auto [from, to] = key;
    const int a = std::min(from, to), b = std::max(from, to);
    if (from == to || vehicles < ec.min_link_vehicles || along.count({from, to}) ||
        (nodes[static_cast<std::size_t>(a)] - nodes[static_cast<std::size_t>(b)]).head<2>().norm() >
            ec.link_max_m)
      continue;
    Street& l = links[{a, b}];
    l.u = a;
    l.v = b;
    (from == a ? l.link_fwd : l.link_bwd) = vehicles;
  }
  for (auto& [key, l] : links) {
    polys.push_back({nodes[static_cast<std::size_t>(l.u)], nodes[static_cast<std::size_t>(l.v)]});
    streets.push_back(std::move(l));
    ++st.short_links;
  }
  st.streets = streets.size();
}

}  // namespace slamroute::roadgraph::detail
