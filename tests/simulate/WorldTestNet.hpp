#pragma once
// Synthetic SUMO nets for the world/sensor tests (no files needed).
#include <string>
#include <vector>

#include "slamroute/core/SumoNet.hpp"
#include "slamroute/simulate/World.hpp"

namespace slamroute::simulate::testnet {

inline void addJunction(SumoNet& net, const std::string& id, double x, double y, double z = 0) {
  SumoJunction j;
  j.id = id;
  j.type = "priority";
  j.pos = Point3(x, y, z);
  net.junction_index[id] = net.junctions.size();
  net.junctions.push_back(j);
}

/// Edge along `centre` with `lanes` lanes of 3.2 m centred on it, lane 0 rightmost (as SUMO).
inline void addEdge(SumoNet& net, const std::string& id, const std::string& from,
                    const std::string& to, const Polyline& centre, int lanes = 1) {
  SumoEdge e;
  e.id = id;
  e.from = from;
  e.to = to;
  for (int k = 0; k < lanes; ++k) {
    SumoLane l;
    l.id = id + "_" + std::to_string(k);
    l.index = k;
    l.width_m = 3.2;
    l.speed_mps = 13.9;
    // lane 0 rightmost: offset to the left of travel by (k - (lanes-1)/2) * width
    const double off = (k - (lanes - 1) / 2.0) * 3.2;
    for (std::size_t i = 0; i < centre.size(); ++i) {
      const Point3 a = centre[i == 0 ? 0 : i - 1], b = centre[i + 1 < centre.size() ? i + 1 : i];
      Eigen::Vector2d d = (b - a).head<2>().normalized();
      Point3 p = centre[i];
      p.head<2>() += Eigen::Vector2d(-d.y(), d.x()) * off;
      l.shape.push_back(p);
    }
    l.length_m = polylineLength(l.shape);
    e.lanes.push_back(l);
  }
  e.shape = centre;
  net.edge_index[id] = net.edges.size();
  net.edges.push_back(e);
}

/// Two-way street between two junctions: each direction one lane, 1.6 m right of the axis.
inline void addStreet(SumoNet& net, const std::string& a, const std::string& b, Polyline axis) {
  auto shift = [](Polyline pl, double off) {
    Polyline out;
    for (std::size_t i = 0; i < pl.size(); ++i) {
      const Point3 p0 = pl[i == 0 ? 0 : i - 1], p1 = pl[i + 1 < pl.size() ? i + 1 : i];
      Eigen::Vector2d d = (p1 - p0).head<2>().normalized();
      Point3 p = pl[i];
      p.head<2>() += Eigen::Vector2d(d.y(), -d.x()) * off;  // right of travel
      out.push_back(p);
    }
    return out;
  };
  addEdge(net, a + "_" + b, a, b, shift(axis, 1.6));
  Polyline rev(axis.rbegin(), axis.rend());
  addEdge(net, b + "_" + a, b, a, shift(rev, 1.6));
}

/// Street W-E along y = 0 at z = 0 (x in [-200, 200]); a one-way two-lane road S->N along
/// x = 0 rising to a deck at z = 7 over |y| < 40 (ramps 40..100 m), flat beyond.
inline SumoNet overpassNet() {
  SumoNet net;
  addJunction(net, "W", -200, 0);
  addJunction(net, "E", 200, 0);
  addJunction(net, "S", 0, -200);
  addJunction(net, "N", 0, 200);
  addStreet(net, "W", "E", {Point3(-200, 0, 0), Point3(200, 0, 0)});
  addEdge(net, "S_N", "S", "N",
          {Point3(0, -200, 0), Point3(0, -100, 0), Point3(0, -40, 7), Point3(0, 40, 7),
           Point3(0, 100, 0), Point3(0, 200, 0)},
          2);
  return net;
}

/// n x n grid of two-way streets, `spacing` metres apart, all at z = 0.
inline SumoNet gridNet(int n, double spacing) {
  SumoNet net;
  auto id = [](int i, int j) { return "J" + std::to_string(i) + "_" + std::to_string(j); };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) addJunction(net, id(i, j), i * spacing, j * spacing);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      if (i + 1 < n)
        addStreet(net, id(i, j), id(i + 1, j),
                  {Point3(i * spacing + 8, j * spacing, 0),
                   Point3((i + 1) * spacing - 8, j * spacing, 0)});
      if (j + 1 < n)
        addStreet(net, id(i, j), id(i, j + 1),
                  {Point3(i * spacing, j * spacing + 8, 0),
                   Point3(i * spacing, (j + 1) * spacing - 8, 0)});
    }
  return net;
}

/// Analytic scenes as plain meshes.
inline void addQuad(TriangleMesh& m, const Point3& a, const Point3& b, const Point3& c,
                    const Point3& d, SurfaceKind k) {
  const int i = static_cast<int>(m.vertices.size());
  for (const Point3& p : {a, b, c, d}) m.vertices.push_back(p.cast<float>());
  m.triangles.emplace_back(i, i + 1, i + 2);
  m.triangles.emplace_back(i, i + 2, i + 3);
  m.kinds.push_back(k);
  m.kinds.push_back(k);
}

/// An infinite-ish wall x = x0 (1 km square), facing -x.
inline TriangleMesh wallAtX(double x0) {
  TriangleMesh m;
  addQuad(m, Point3(x0, -500, -500), Point3(x0, -500, 500), Point3(x0, 500, 500),
          Point3(x0, 500, -500), SurfaceKind::Wall);
  return m;
}

/// Closed cube room [-h, h]^3 around the origin.
inline TriangleMesh room(double h) {
  TriangleMesh m;
  const Point3 p[8] = {{-h, -h, -h}, {h, -h, -h}, {h, h, -h}, {-h, h, -h},
                       {-h, -h, h},  {h, -h, h},  {h, h, h},  {-h, h, h}};
  addQuad(m, p[0], p[1], p[2], p[3], SurfaceKind::Ground);
  addQuad(m, p[4], p[7], p[6], p[5], SurfaceKind::Building);
  addQuad(m, p[0], p[4], p[5], p[1], SurfaceKind::Building);
  addQuad(m, p[1], p[5], p[6], p[2], SurfaceKind::Building);
  addQuad(m, p[2], p[6], p[7], p[3], SurfaceKind::Building);
  addQuad(m, p[3], p[7], p[4], p[0], SurfaceKind::Building);
  return m;
}

}  // namespace slamroute::simulate::testnet
