// A street split in two at a node placed part-way along it: a T junction whose side street ends
// at the stop line (StopLineEnds.cpp), a junction at a bend where survey vehicles set off
// (BendEnds.cpp), a place where vehicles turn round (TurningPlaces.cpp).
#include "Streets.hpp"

namespace slamroute::roadgraph::detail {

void splitStreet(std::vector<Street>& streets, std::size_t k, double arc, int node,
                 const std::vector<Point3>& sp) {
  Street tail = streets[k];
  Street& head = streets[k];
  const Polyline c = head.centre;
  head.centre.clear();
  tail.centre.clear();
  double s = 0.0;
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (i > 0) s += (c[i] - c[i - 1]).norm();
    (s < arc ? head.centre : tail.centre).push_back(c[i]);
  }
  const std::vector<int> members = head.members;
  head.members.clear();
  tail.members.clear();
  for (int i : members)
    (arcPosition(c, sp[static_cast<std::size_t>(i)]) < arc ? head.members : tail.members)
        .push_back(i);
  head.v = node;
  tail.u = node;
  streets.push_back(std::move(tail));
}

int degreeOf(const std::vector<Street>& streets, int n) {
  int d = 0;
  for (const auto& s : streets) d += (s.u == n) + (s.v == n);
  return d;
}

int insertIntersection(GraphNodes& gn, std::vector<Street>& streets, const Point3& p) {
  const int at = static_cast<int>(gn.n_inter);
  for (auto& s : streets) {
    if (s.u >= at) ++s.u;
    if (s.v >= at) ++s.v;
  }
  gn.pos.insert(gn.pos.begin() + at, p);
  gn.is_end.insert(gn.is_end.begin() + at, 0);
  ++gn.n_inter;
  return at;
}

int joinDeadEnds(GraphNodes& gn, std::vector<Street>& streets, const StreetPoints& spts,
                 double heading_m,
                 const std::function<std::optional<PointOnStreet>(std::size_t, const Point3&,
                                                                  const Eigen::Vector2d&)>& find) {
  int joined = 0;
  for (std::size_t k = 0; k < streets.size(); ++k)
    for (const bool at_u : {true, false}) {
      const int end = at_u ? streets[k].u : streets[k].v;
      if (streets[k].comp < 0 || !gn.is_end[static_cast<std::size_t>(end)] ||
          degreeOf(streets, end) != 1)
        continue;
      const auto [tip, dir] = tipAndHeading(streets[k].centre, at_u, heading_m);
      if (dir.isZero()) continue;
      const std::optional<PointOnStreet> x = find(k, tip, dir);
      if (!x) continue;
      const int node = insertIntersection(gn, streets, x->at);
      splitStreet(streets, x->street, x->arc, node, spts.pts);
      (at_u ? streets[k].u : streets[k].v) = node;
      ++joined;
    }
  return joined;
}

}  // namespace slamroute::roadgraph::detail
