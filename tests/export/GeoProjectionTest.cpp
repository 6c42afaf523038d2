// Net x/y <-> WGS84 with PROJ: known junction positions, round trips, nets without a
// geo-reference, bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "SumoToolsNets.hpp"
#include "TestNets.hpp"
#include "TestTmp.hpp"
#include "slamroute/export/GeoProjection.hpp"

namespace slamroute::exports {
namespace {

double metresBetween(const LonLat& a, const LonLat& b) {
  const double lat = 0.5 * (a.lat_deg + b.lat_deg) * M_PI / 180.0;
  const double dx = (a.lon_deg - b.lon_deg) * M_PI / 180.0 * 6371000.0 * std::cos(lat);
  const double dy = (a.lat_deg - b.lat_deg) * M_PI / 180.0 * 6371000.0;
  return std::hypot(dx, dy);
}

TEST(GeoProjection, JunctionsOfANetBuiltFromLonLatMapBackToTheirLonLat) {
  // netconvert projects the nodes' lon/lat to UTM and shifts them by netOffset; converting the
  // junctions back must give the lon/lat they were built from (netconvert rounds to 1 cm).
  const SumoNet net = SumoNet::read(test::geoPlusNet(test::testTmp()));
  ASSERT_TRUE(hasGeoReference(net));
  const auto proj = GeoProjection::forNet(net, std::nullopt);
  ASSERT_TRUE(proj);
  EXPECT_NE(proj->definition().find("+proj=utm"), std::string::npos);
  for (const auto& g : test::kGeoPlus) {
    const SumoJunction* j = net.findJunction(g.id);
    ASSERT_NE(j, nullptr) << g.id;
    const LonLat ll = proj->toLonLat(j->pos.head<2>());
    EXPECT_LT(metresBetween(ll, {g.lon, g.lat}), 0.02) << g.id;
  }
  // Grid convergence: UTM north is not true north here, so N lies east of C in net x.
  EXPECT_GT(net.findJunction("N")->pos.x() - net.findJunction("C")->pos.x(), 1.0);
}

TEST(GeoProjection, OsmNetRoundTripsWithinACentimetreAndStaysInItsOrigBoundary) {
  const SumoNet net = SumoNet::read(test::adlershofNet());
  const auto proj = GeoProjection::forNet(net, std::nullopt);
  ASSERT_TRUE(proj);
  double lon0, lat0, lon1, lat1;
  ASSERT_EQ(std::sscanf(net.location.orig_boundary.c_str(), "%lf,%lf,%lf,%lf", &lon0, &lat0, &lon1,
                        &lat1),
            4);
  ASSERT_GT(net.junctions.size(), 1000u);
  // origBoundary is written with 6 decimals: a junction on its edge may be 5e-7 deg outside.
  const double eps = 1e-6;
  double worst = 0.0;
  for (const auto& j : net.junctions) {
    const LonLat ll = proj->toLonLat(j.pos.head<2>());
    EXPECT_TRUE(ll.lon_deg >= lon0 - eps && ll.lon_deg <= lon1 + eps && ll.lat_deg >= lat0 - eps &&
                ll.lat_deg <= lat1 + eps)
        << j.id << " at " << ll.lon_deg << "," << ll.lat_deg;
    worst = std::max(worst, (proj->toNet(ll) - j.pos.head<2>()).norm());
  }
  EXPECT_LT(worst, 0.01);
}

TEST(GeoProjection, OsmNetStreetsLieWhereTheyAreInBerlinAdlershof) {
  const SumoNet net = SumoNet::read(test::adlershofNet());
  const auto proj = GeoProjection::forNet(net, std::nullopt);
  ASSERT_TRUE(proj);
  // Rudower Chaussee is Adlershof's main street; it starts at S-Bahnhof Adlershof
  // (52.4351 N, 13.5413 E) and runs about 2 km south-west.
  const LonLat station{13.5413, 52.4351};
  int seen = 0;
  double nearest = 1e9;
  for (const auto& e : net.edges) {
    if (e.name != "Rudower Chaussee") continue;
    ++seen;
    for (const auto& p : e.shape) {
      const double d = metresBetween(proj->toLonLat(p.head<2>()), station);
      EXPECT_LT(d, 2500.0) << e.id;
      nearest = std::min(nearest, d);
    }
  }
  EXPECT_GT(seen, 3);
  EXPECT_LT(nearest, 400.0);
}

TEST(GeoProjection, NetWithoutGeoReferenceNeedsAnOrigin) {
  const SumoNet net =
      SumoNet::read(std::string(SLAMROUTE_SOURCE_DIR) + "/networks/test/plus.net.xml");
  EXPECT_FALSE(hasGeoReference(net));
  EXPECT_FALSE(GeoProjection::forNet(net, std::nullopt));
  const auto proj = GeoProjection::forNet(net, GeoOrigin{52.52, 13.405});
  ASSERT_TRUE(proj);
  // The convBoundary's centre is the plus centre C (500, 500): it lands on the origin.
  const Point2 c = boundaryCentre(net.location.conv_boundary);
  EXPECT_NEAR(c.x(), 500.0, 1e-9);
  const LonLat at_c = proj->toLonLat(c);
  EXPECT_NEAR(at_c.lat_deg, 52.52, 1e-9);
  EXPECT_NEAR(at_c.lon_deg, 13.405, 1e-9);
  // 150 m east and north (E and N ends) are 150 m away on the ground, in the right direction.
  const LonLat at_e = proj->toLonLat({650.0, 500.0}), at_n = proj->toLonLat({500.0, 650.0});
  EXPECT_NEAR(metresBetween(at_e, at_c), 150.0, 0.5);
  EXPECT_NEAR(metresBetween(at_n, at_c), 150.0, 0.5);
  EXPECT_GT(at_e.lon_deg, 13.405);
  EXPECT_GT(at_n.lat_deg, 52.52);
  EXPECT_LT((proj->toNet(at_e) - Point2(650.0, 500.0)).norm(), 0.01);
}

TEST(GeoProjection, ParsesTheOriginAndRejectsBadOnes) {
  const GeoOrigin o = parseGeoOrigin("52.52, 13.405", "--geo-origin");
  EXPECT_DOUBLE_EQ(o.lat_deg, 52.52);
  EXPECT_DOUBLE_EQ(o.lon_deg, 13.405);
  for (const char* bad : {"", "52.52", "91,10", "10,181", "a,b", "52.5,13x", "nan,1"})
    EXPECT_THROW(parseGeoOrigin(bad, "--geo-origin"), std::invalid_argument) << bad;
}

TEST(GeoProjection, UnusableProjParameterNamesTheNet) {
  SumoNet net;
  net.source = "broken.net.xml";
  net.location.proj_parameter = "+proj=nosuchprojection +ellps=WGS84";
  try {
    GeoProjection::forNet(net, std::nullopt);
    FAIL() << "expected an error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("broken.net.xml"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace slamroute::exports
