// The shipped networks (networks/, made by networks/generate.py) read with SumoNet::read: counts
// known by construction, the overpass really elevated with no junction at its crossing, and the
// default city strongly connected with a plausible size.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>

#include "slamroute/core/DriveGraph.hpp"
#include "slamroute/core/SumoNet.hpp"

namespace slamroute {
namespace {

std::filesystem::path shipped(const std::string& rel) {
  return std::filesystem::path(SLAMROUTE_SOURCE_DIR) / "networks" / rel;
}

double maxZ(const Polyline& pl) {
  double z = -1e9;
  for (const auto& p : pl) z = std::max(z, p.z());
  return z;
}

/// z of the polyline where it passes closest (in 2D) to `xy`, and that 2D distance.
std::pair<double, double> zNear(const Polyline& pl, const Point2& xy) {
  double best_d = 1e18, best_z = 0.0;
  for (std::size_t i = 0; i + 1 < pl.size(); ++i) {
    const Point2 a = pl[i].head<2>(), b = pl[i + 1].head<2>();
    const double l2 = (b - a).squaredNorm();
    const double t = l2 == 0.0 ? 0.0 : std::clamp((xy - a).dot(b - a) / l2, 0.0, 1.0);
    const double d = (a + t * (b - a) - xy).norm();
    if (d < best_d) {
      best_d = d;
      best_z = pl[i].z() + t * (pl[i + 1].z() - pl[i].z());
    }
  }
  return {best_z, best_d};
}

double nearestJunction(const SumoNet& net, const Point2& xy) {
  double d = 1e18;
  for (const auto& j : net.junctions) d = std::min(d, (j.pos.head<2>() - xy).norm());
  return d;
}

/// Number of distinct neighbouring junctions of every junction over passenger edges.
std::map<std::string, std::size_t> passengerDegree(const SumoNet& net) {
  std::map<std::string, std::set<std::string>> nb;
  for (const auto& e : net.edges) {
    if (!e.allowsPassenger()) continue;
    nb[e.from].insert(e.to);
    nb[e.to].insert(e.from);
  }
  std::map<std::string, std::size_t> deg;
  for (const auto& j : net.junctions) deg[j.id] = nb[j.id].size();
  return deg;
}

std::size_t countDegree(const std::map<std::string, std::size_t>& deg, std::size_t k) {
  return static_cast<std::size_t>(
      std::count_if(deg.begin(), deg.end(), [k](const auto& kv) { return kv.second == k; }));
}

std::size_t twoWayEdges(const SumoNet& net) {
  std::set<std::pair<std::string, std::string>> dirs;
  for (const auto& e : net.edges)
    if (e.allowsPassenger()) dirs.insert({e.from, e.to});
  std::size_t n = 0;
  for (const auto& [a, b] : dirs) n += dirs.count({b, a});
  return n;
}

// ---------------------------------------------------------------------------------------------
// networks/test/plus.net.xml: junction C at (500, 500) and four two-way arms of 150 m.

TEST(ShippedNetworks, PlusHasOneCrossingAndFourDeadEndArms) {
  const SumoNet net = SumoNet::read(shipped("test/plus.net.xml"));
  const NetworkInfo info = networkInfo(net);
  EXPECT_EQ(info.junctions, 5u);        // C + N, E, S, W
  EXPECT_EQ(info.passenger_edges, 8u);  // 4 arms, both directions
  EXPECT_EQ(info.lscc_junctions, 5u);   // dead ends are turned at (netconvert's turnarounds)
  EXPECT_EQ(info.lscc_edges, 8u);
  // Lanes stop at the junction shapes, so each edge is a little shorter than its 150 m arm.
  EXPECT_GT(info.total_length_m, 8 * 130.0);
  EXPECT_LE(info.total_length_m, 8 * 150.0 + 1e-6);
  const auto deg = passengerDegree(net);
  EXPECT_EQ(deg.at("C"), 4u);
  EXPECT_EQ(countDegree(deg, 1), 4u);
  const SumoJunction* c = net.findJunction("C");
  ASSERT_NE(c, nullptr);
  EXPECT_NEAR(c->pos.x(), 500.0, 1e-6);  // generated with --offset.disable-normalization
  EXPECT_NEAR(c->pos.y(), 500.0, 1e-6);
}

// networks/test/grid3x3.net.xml: 3 x 3 junctions 200 m apart, 12 two-way streets.

TEST(ShippedNetworks, Grid3x3HasNineJunctionsAndTwelveTwoWayStreets) {
  const SumoNet net = SumoNet::read(shipped("test/grid3x3.net.xml"));
  const NetworkInfo info = networkInfo(net);
  EXPECT_EQ(info.junctions, 9u);
  EXPECT_EQ(info.passenger_edges, 24u);  // 2 * (3 rows * 2 + 3 columns * 2)
  EXPECT_EQ(info.lscc_junctions, 9u);
  EXPECT_EQ(info.lscc_edges, 24u);
  EXPECT_GT(info.total_length_m, 24 * 180.0);
  EXPECT_LE(info.total_length_m, 24 * 200.0 + 1e-6);
  const auto deg = passengerDegree(net);
  EXPECT_EQ(countDegree(deg, 2), 4u);  // corners
  EXPECT_EQ(countDegree(deg, 3), 4u);  // edge midpoints
  EXPECT_EQ(countDegree(deg, 4), 1u);  // centre
  EXPECT_EQ(twoWayEdges(net), 24u);
}

// networks/test/ring.net.xml: one-way ring of 8 junctions on a circle of radius 160 m.

TEST(ShippedNetworks, RingIsOneStronglyConnectedLoopOfAboutOneKilometre) {
  const SumoNet net = SumoNet::read(shipped("test/ring.net.xml"));
  const NetworkInfo info = networkInfo(net);
  EXPECT_EQ(info.junctions, 8u);
  EXPECT_EQ(info.passenger_edges, 8u);
  EXPECT_EQ(info.lscc_junctions, 8u);
  EXPECT_EQ(info.lscc_edges, 8u);
  const double circumference = 2.0 * M_PI * 160.0;  // 1005 m; lanes run a bit off the centre line
  EXPECT_NEAR(info.total_length_m, circumference, 0.05 * circumference);
  EXPECT_EQ(twoWayEdges(net), 0u);
  for (const auto& j : net.junctions)
    EXPECT_NEAR((j.pos.head<2>() - Point2(500.0, 500.0)).norm(), 160.0, 0.02) << j.id;
}

// networks/test/overpass.net.xml: diamond W(250,500) S(500,250) E(750,500) N(500,750); the
// street W-E (z = 0) and the elevated road S-N (6 m deck) cross at (500, 500) with no junction.

TEST(ShippedNetworks, OverpassIsElevatedWithNoJunctionAtTheCrossing) {
  const SumoNet net = SumoNet::read(shipped("test/overpass.net.xml"));
  const NetworkInfo info = networkInfo(net);
  EXPECT_EQ(info.junctions, 4u);
  EXPECT_EQ(info.passenger_edges, 12u);  // 6 two-way roads
  EXPECT_EQ(info.lscc_junctions, 4u);
  EXPECT_EQ(info.lscc_edges, 12u);

  const Point2 crossing(500.0, 500.0);
  EXPECT_GT(nearestJunction(net, crossing), 200.0);
  for (const char* id : {"S_N", "N_S"}) {
    const SumoEdge* e = net.findEdge(id);
    ASSERT_NE(e, nullptr) << id;
    EXPECT_GE(maxZ(e->shape), 5.0) << id;
    for (const auto& lane : e->lanes) {
      const auto [z, d] = zNear(lane.shape, crossing);
      EXPECT_LT(d, 5.0) << lane.id;
      EXPECT_NEAR(z, 6.0, 0.05) << lane.id;  // the deck, carried into the lane shapes
    }
    // ramps end at ground level (the lane shape stops a few metres into the ramp, where the
    // road has risen by a few centimetres)
    EXPECT_NEAR(e->shape.front().z(), 0.0, 0.25);
    EXPECT_NEAR(e->shape.back().z(), 0.0, 0.25);
  }
  for (const char* id : {"W_E", "E_W"}) {
    const SumoEdge* e = net.findEdge(id);
    ASSERT_NE(e, nullptr) << id;
    const auto [z, d] = zNear(e->lanes.at(0).shape, crossing);
    EXPECT_LT(d, 5.0) << id;
    EXPECT_NEAR(z, 0.0, 1e-9) << id;
  }
  for (const auto& j : net.junctions) EXPECT_NEAR(j.pos.z(), 0.0, 1e-9) << j.id;
}

// ---------------------------------------------------------------------------------------------
// networks/default_city/default_city.net.xml: 5 rows x 6 columns of straight streets (see the
// ROWS / COLS / MISSING / STUBS tables of networks/generate.py).
//
// Junctions: 30 line crossings - 1 grade-separated (R2 flies over C2) - 3 through-points where
// the cross street is missing on both sides (R4C1, R0C3, R1C5) = 26, + 4 stub T-junctions
// (T0..T3) + 4 dead ends (D0..D3) = 34.
// Street pieces (junction to junction): R0 4, R1 4, R2 4, R3 4, R4 5, C0 5, C1 3, C2 3, C3 3,
// C4 4, C5 4, stubs 4 = 47; two-way are R0, R2, C0, C2, C4 and the stubs (24 pieces), one-way
// R1, R3, R4, C1, C3, C5 (23 pieces): 2 * 24 + 23 = 71 passenger edges.
// 4-way junctions: R1C1, R1C2, R2C1, R2C3, R2C4, R3C2; corners (2 neighbours): R0C0, R0C1, R0C2,
// R0C5, R4C0, R4C5; dead ends: D0..D3; the other 18 are T-junctions. Traffic lights at the
// 4-way junctions on an avenue (R2, C2, C4): all but R1C1.

TEST(ShippedNetworks, DefaultCityCountsByConstruction) {
  const SumoNet net = SumoNet::read(shipped("default_city/default_city.net.xml"));
  const NetworkInfo info = networkInfo(net);
  EXPECT_EQ(info.junctions, 34u);
  EXPECT_EQ(info.passenger_edges, 71u);
  EXPECT_EQ(twoWayEdges(net), 48u);

  const auto deg = passengerDegree(net);
  EXPECT_EQ(countDegree(deg, 1), 4u);
  EXPECT_EQ(countDegree(deg, 2), 6u);
  EXPECT_EQ(countDegree(deg, 3), 18u);
  EXPECT_EQ(countDegree(deg, 4), 6u);
  for (const char* d : {"D0", "D1", "D2", "D3"}) EXPECT_EQ(deg.at(d), 1u) << d;

  std::set<std::string> tls;
  for (const auto& j : net.junctions)
    if (j.type == "traffic_light") tls.insert(j.id);
  EXPECT_EQ(tls, (std::set<std::string>{"R1C2", "R2C1", "R2C3", "R2C4", "R3C2"}));

  for (const auto& e : net.edges) {
    if (e.type == "avenue") {
      EXPECT_EQ(e.lanes.size(), 2u) << e.id;
      EXPECT_NEAR(e.speed(), 16.67, 1e-6) << e.id;
    } else {
      EXPECT_EQ(e.type, "street") << e.id;
      EXPECT_EQ(e.lanes.size(), 1u) << e.id;
      EXPECT_NEAR(e.speed(), 13.89, 1e-6) << e.id;
    }
  }
}

TEST(ShippedNetworks, DefaultCityIsStronglyConnectedAndSizedForATenToFifteenKmRoute) {
  const SumoNet net = SumoNet::read(shipped("default_city/default_city.net.xml"));
  const NetworkInfo info = networkInfo(net);
  // Required: the largest strongly connected part holds >= 90 % of the passenger edges; by
  // construction (one-way streets alternate, dead ends are two-way) it holds all of them.
  EXPECT_GE(info.lscc_edges * 10, info.passenger_edges * 9);
  EXPECT_EQ(info.lscc_edges, info.passenger_edges);
  EXPECT_EQ(info.lscc_junctions, info.junctions);

  // Sum of passenger edges (a two-way street counts twice): with ~8.7 km of streets a route
  // covering every street is ~10-15 km.
  EXPECT_GT(info.total_length_m, 9000.0);
  EXPECT_LT(info.total_length_m, 15000.0);

  // Roughly 1 x 1 km, and no two junctions closer than 35 m (the road-graph extraction's
  // cylinder is 25 m).
  double xmin = 1e18, xmax = -1e18, ymin = 1e18, ymax = -1e18, closest = 1e18;
  for (std::size_t i = 0; i < net.junctions.size(); ++i) {
    const Point3& p = net.junctions[i].pos;
    xmin = std::min(xmin, p.x()), xmax = std::max(xmax, p.x());
    ymin = std::min(ymin, p.y()), ymax = std::max(ymax, p.y());
    for (std::size_t k = i + 1; k < net.junctions.size(); ++k)
      closest = std::min(closest, (p.head<2>() - net.junctions[k].pos.head<2>()).norm());
  }
  EXPECT_NEAR(xmax - xmin, 1000.0, 100.0);
  EXPECT_NEAR(ymax - ymin, 1000.0, 100.0);
  EXPECT_GE(closest, 35.0);
}

TEST(ShippedNetworks, DefaultCityAvenueFliesOverTheCrossingAvenue) {
  const SumoNet net = SumoNet::read(shipped("default_city/default_city.net.xml"));
  // Crossing of row R2 (y = 450 - 0.03 (x - 500)) and column C2 (x = 430 + 0.07 (y - 450)).
  const double y = (450.0 - 0.03 * (430.0 - 0.07 * 450.0 - 500.0)) / (1.0 + 0.03 * 0.07);
  const Point2 crossing(430.0 + 0.07 * (y - 450.0), y);
  EXPECT_GT(nearestJunction(net, crossing), 150.0);
  EXPECT_EQ(net.findJunction("R2C2"), nullptr);

  for (const char* id : {"R2C1_R2C3", "R2C3_R2C1"}) {  // the overpass, both directions
    const SumoEdge* e = net.findEdge(id);
    ASSERT_NE(e, nullptr) << id;
    EXPECT_GE(maxZ(e->shape), 5.0) << id;
    for (const auto& lane : e->lanes) {
      const auto [z, d] = zNear(lane.shape, crossing);
      EXPECT_LT(d, 8.0) << lane.id;
      EXPECT_NEAR(z, 6.5, 0.05) << lane.id;
    }
  }
  for (const char* id : {"R1C2_R3C2", "R3C2_R1C2"}) {  // the avenue passing under
    const SumoEdge* e = net.findEdge(id);
    ASSERT_NE(e, nullptr) << id;
    for (const auto& lane : e->lanes) {
      const auto [z, d] = zNear(lane.shape, crossing);
      EXPECT_LT(d, 8.0) << lane.id;
      EXPECT_NEAR(z, 0.0, 1e-9) << lane.id;
    }
  }
  // Only the overpass is off the ground.
  for (const auto& e : net.edges) {
    const bool overpass = e.id == "R2C1_R2C3" || e.id == "R2C3_R2C1";
    if (!overpass) {
      EXPECT_LT(maxZ(e.shape), 1e-9) << e.id;
    }
  }
}

}  // namespace
}  // namespace slamroute
