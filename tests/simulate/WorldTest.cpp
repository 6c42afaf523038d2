#include "TestTmp.hpp"
#include "slamroute/simulate/World.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>

#include "WorldTestNet.hpp"

namespace slamroute::simulate {
namespace {

namespace fs = std::filesystem;

fs::path tmpDir(const std::string& name) {
  const fs::path d = slamroute::test::testTmp() / "world" / name;
  fs::create_directories(d);
  return d;
}

TEST(World, OverpassDeckIsAboveTheStreetAndTheStreetPassesUnder) {
  const World w = World::build(testnet::overpassNet(), WorldConfig{}, 7);
  // vertical ray up from the W->E lane (y = -1.6) under the deck (x = 0): deck bottom at 7 - 1
  const RayHit up = w.castRay(Point3(0, -1.6, 0.5), Vec3::UnitZ(), 50);
  ASSERT_TRUE(up.hit);
  // (the deck's surface has camber and relief: a few cm)
  EXPECT_NEAR(up.range_m, 7.0 - WorldConfig{}.deck_thickness_m - 0.5, 0.1);
  EXPECT_EQ(up.kind, SurfaceKind::Deck);
  // from above: the deck's road surface at z = 7
  const RayHit down = w.castRay(Point3(1.6, 0, 30), -Vec3::UnitZ(), 100);
  ASSERT_TRUE(down.hit);
  EXPECT_NEAR(30 - down.range_m, 7.0, 0.1);
  EXPECT_EQ(down.kind, SurfaceKind::Road);
  // the street below is free: a ray along it at sensor height sees no pillar or wall
  for (double y : {-1.6, 1.6}) {
    const RayHit along = w.castRay(Point3(-150, y, 1.8), Vec3::UnitX(), 300);
    EXPECT_FALSE(along.hit && along.range_m < 300)
        << "blocked at x = " << -150 + along.range_m << " by " << surfaceKindName(along.kind);
  }
  EXPECT_GT(w.stats().pillars, 0u);
}

TEST(World, ShippedOverpassNetHasADeckOverTheStreet) {
  const fs::path net = fs::path(SLAMROUTE_SOURCE_DIR) / "networks/test/overpass.net.xml";
  ASSERT_TRUE(fs::exists(net)) << net << " missing";
  const SumoNet sn = SumoNet::read(net);
  const World w = World::build(sn, WorldConfig{}, 42);
  const SumoEdge* we = sn.findEdge("W_E");
  ASSERT_NE(we, nullptr);
  // the W_E lane point nearest to x = 500 (under the S_N deck at z = 6)
  const Polyline& lane = we->lanes.front().shape;
  const double y = lane.front().y();
  const RayHit up = w.castRay(Point3(500, y, 0.5), Vec3::UnitZ(), 50);
  ASSERT_TRUE(up.hit);
  EXPECT_NEAR(0.5 + up.range_m, 6.0 - WorldConfig{}.deck_thickness_m, 0.3);
  EXPECT_EQ(up.kind, SurfaceKind::Deck);
}

TEST(World, SameSeedSameMeshOtherSeedOtherMesh) {
  const SumoNet net = testnet::gridNet(3, 160);
  const World a = World::build(net, WorldConfig{}, 11), b = World::build(net, WorldConfig{}, 11);
  const World c = World::build(net, WorldConfig{}, 12);
  ASSERT_EQ(a.mesh().vertices.size(), b.mesh().vertices.size());
  ASSERT_EQ(a.mesh().triangles.size(), b.mesh().triangles.size());
  for (std::size_t i = 0; i < a.mesh().vertices.size(); ++i)
    ASSERT_EQ(a.mesh().vertices[i], b.mesh().vertices[i]) << "vertex " << i;
  for (std::size_t i = 0; i < a.mesh().triangles.size(); ++i)
    ASSERT_EQ(a.mesh().triangles[i], b.mesh().triangles[i]) << "triangle " << i;
  EXPECT_NE(a.mesh().vertices.size(), c.mesh().vertices.size());
}

/// Vertical rays from above onto every lane (centre and both borders, every metre) must land on
/// road surfaces: no building, wall or tree stands on a road.
void expectRoadsFree(const SumoNet& net, const World& w) {
  std::size_t n = 0;
  for (const auto& e : net.edges)
    for (const auto& l : e.lanes)
      for (std::size_t i = 0; i + 1 < l.shape.size(); ++i) {
        const Vec3 d = l.shape[i + 1] - l.shape[i];
        const double len = d.head<2>().norm();
        const Eigen::Vector2d side = Eigen::Vector2d(-d.y(), d.x()) / len;
        for (double s = 0.25; s <= len - 0.25; s += 1.0)
          for (double off : {-0.45, 0.0, 0.45}) {
            Point3 p = l.shape[i] + d * (s / len);
            p.head<2>() += side * off * l.width_m;
            const RayHit h = w.castRay(Point3(p.x(), p.y(), 200), -Vec3::UnitZ(), 400);
            ASSERT_TRUE(h.hit);
            const SurfaceKind k = h.kind;
            ASSERT_TRUE(k == SurfaceKind::Road || k == SurfaceKind::Deck ||
                        k == SurfaceKind::Sidewalk || k == SurfaceKind::Parapet)
                << "lane " << l.id << " at (" << p.x() << ", " << p.y() << ") is covered by "
                << surfaceKindName(k);
            ++n;
          }
      }
  EXPECT_GT(n, 100u);
}

TEST(World, BuildingsNeverStandOnRoads) {
  const SumoNet grid = testnet::gridNet(4, 150);
  const World w = World::build(grid, WorldConfig{}, 3);
  EXPECT_GT(w.stats().buildings, 10u);
  expectRoadsFree(grid, w);
  const SumoNet over = testnet::overpassNet();
  expectRoadsFree(over, World::build(over, WorldConfig{}, 3));
}

TEST(World, DefaultCityIsPlausible) {
  const fs::path net_path =
      fs::path(SLAMROUTE_SOURCE_DIR) / "networks/default_city/default_city.net.xml";
  ASSERT_TRUE(fs::exists(net_path)) << net_path << " missing";
  const SumoNet net = SumoNet::read(net_path);
  const World w = World::build(net, WorldConfig{}, 42);
  const WorldStats& s = w.stats();
  EXPECT_GT(s.buildings, 100u);
  EXPECT_GT(s.trees, 50u);
  EXPECT_GT(s.pillars, 0u);  // the default city has an overpass
  EXPECT_GT(s.streets_rich, 0u);
  EXPECT_GT(s.streets_wall, 0u);
  EXPECT_GT(s.streets_open, 0u);
  expectRoadsFree(net, w);
  // test artifact: look at it
  w.renderTopDownPng(tmpDir("default_city") / "default_city_topdown.png", 0.5);
}

TEST(World, StreetsLinedWithBuildingsScoreHigherThanOpenFields) {
  const SumoNet net = testnet::gridNet(5, 150);
  const World w = World::build(net, WorldConfig{}, 5);
  std::map<StreetKind, std::vector<double>> by_kind;
  for (const auto& e : net.edges) {
    const double r = w.streetRichness(e.id);
    EXPECT_GE(r, 0.0);
    EXPECT_LE(r, 1.0);
    by_kind[w.streetKind(e.id)].push_back(r);
  }
  ASSERT_FALSE(by_kind[StreetKind::Rich].empty());
  ASSERT_FALSE(by_kind[StreetKind::Open].empty());
  ASSERT_FALSE(by_kind[StreetKind::Wall].empty());
  auto mean = [](const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += x;
    return s / static_cast<double>(v.size());
  };
  const double rich = mean(by_kind[StreetKind::Rich]), wall = mean(by_kind[StreetKind::Wall]),
               open = mean(by_kind[StreetKind::Open]);
  EXPECT_GT(rich, wall + 0.1);
  EXPECT_GT(wall, open + 0.1);
  double min_rich = 1, max_open = 0;
  for (double r : by_kind[StreetKind::Rich]) min_rich = std::min(min_rich, r);
  for (double r : by_kind[StreetKind::Open]) max_open = std::max(max_open, r);
  EXPECT_GT(min_rich, max_open);
  // both directions of a street share the class
  EXPECT_EQ(w.streetKind("J0_0_J1_0"), w.streetKind("J1_0_J0_0"));
  EXPECT_THROW(w.streetKind("nope"), std::invalid_argument);
}

TEST(World, WritesPlyObjAndTopDownPng) {
  const World w = World::build(testnet::overpassNet(), WorldConfig{}, 1);
  const fs::path d = tmpDir("export");
  w.writePly(d / "world.ply");
  w.writeObj(d / "world.obj");
  w.renderTopDownPng(d / "world.png", 1.0);
  std::ifstream in(d / "world.ply", std::ios::binary);
  std::string line, header;
  while (std::getline(in, line)) {
    header += line + "\n";
    if (line == "end_header") break;
  }
  EXPECT_NE(header.find("format binary_little_endian 1.0"), std::string::npos);
  EXPECT_NE(header.find("element vertex " + std::to_string(w.mesh().vertices.size())),
            std::string::npos);
  EXPECT_NE(header.find("element face " + std::to_string(w.mesh().triangles.size())),
            std::string::npos);
  EXPECT_EQ(fs::file_size(d / "world.ply"),
            header.size() + 12 * w.mesh().vertices.size() + 13 * w.mesh().triangles.size());
  EXPECT_GT(fs::file_size(d / "world.png"), 1000u);
  EXPECT_GT(fs::file_size(d / "world.obj"), 1000u);
}

TEST(World, RejectsBadConfig) {
  WorldConfig c;
  c.rich_share = 0.9;
  c.wall_share = 0.5;
  EXPECT_THROW(World::build(testnet::overpassNet(), c, 1), std::invalid_argument);
  WorldConfig p;
  p.poly_file = "/nonexistent/x.poly.xml";
  EXPECT_THROW(World::build(testnet::overpassNet(), p, 1), std::invalid_argument);
}

TEST(World, PolyFileBuildingsAreUsed) {
  const fs::path d = tmpDir("poly");
  std::ofstream(d / "b.poly.xml")
      << "<additional>\n"
         "<poly id=\"b1\" type=\"building\" shape=\"20,20 40,20 40,40 20,40\"><param "
         "key=\"height\" value=\"12\"/></poly>\n"
         "<poly id=\"onroad\" type=\"building\" shape=\"-10,-5 10,-5 10,5 -10,5\"/>\n"
         "<poly id=\"park\" type=\"park\" shape=\"-60,20 -40,20 -40,40\"/>\n"
         "</additional>\n";
  WorldConfig c;
  c.poly_file = (d / "b.poly.xml").string();
  const World w = World::build(testnet::overpassNet(), c, 1);
  EXPECT_EQ(w.stats().buildings, 1u);  // the one over the road is dropped, the park ignored
  const RayHit h = w.castRay(Point3(30, 30, 50), -Vec3::UnitZ(), 100);
  ASSERT_TRUE(h.hit);
  EXPECT_EQ(h.kind, SurfaceKind::Building);
  EXPECT_NEAR(50 - h.range_m, 12.0, 1e-3);
}

}  // namespace
}  // namespace slamroute::simulate
