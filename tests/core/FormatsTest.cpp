// Trajectory, route, scan and config file formats; atomic writing.
#include <gtest/gtest.h>

#include <cmath>

#include "TestUtil.hpp"
#include "slamroute/core/AtomicFile.hpp"
#include "slamroute/core/ConfigIO.hpp"
#include "slamroute/core/Route.hpp"
#include "slamroute/core/Scan.hpp"
#include "slamroute/core/Trajectory.hpp"

namespace slamroute {
namespace {

TEST(Trajectory, TumAndKittiRoundTrip) {
  const auto dir = test::tempDir("traj");
  Trajectory t;
  for (int i = 0; i < 5; ++i) {
    StampedPose p;
    p.t = 0.1 * i;
    p.T_world_body =
        Eigen::Translation3d(i, 2.0 * i, 0.5) * Eigen::AngleAxisd(0.3 * i, Vec3::UnitZ());
    t.push_back(p);
  }
  writeTum(dir / "a.tum", t);
  writeKittiPoses(dir / "a.kitti", t);
  for (const auto& r : {readTrajectory(dir / "a.tum"), readTrajectory(dir / "a.kitti")}) {
    ASSERT_EQ(r.size(), 5u);
    for (int i = 0; i < 5; ++i) {
      EXPECT_NEAR((r[i].T_world_body.matrix() - t[i].T_world_body.matrix()).norm(), 0.0, 1e-5);
      EXPECT_NEAR(r[i].t, t[i].t, 1e-6);
    }
  }
}

TEST(Trajectory, MalformedLineNamesFileAndLine) {
  const auto dir = test::tempDir("traj_bad");
  test::writeText(dir / "b.tum", "# header\n0 0 0 0 0 0 0 1\n0.1 1 x 0 0 0 0 1\n");
  try {
    readTum(dir / "b.tum");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("b.tum:3"), std::string::npos) << e.what();
  }
  test::writeText(dir / "c.tum", "0 0 0 0 0 0 1\n");
  EXPECT_THROW(readTum(dir / "c.tum"), std::invalid_argument);
}

TEST(Route, PlainListAndRoundTrip) {
  const auto dir = test::tempDir("route");
  test::writeText(dir / "plain.json", R"(["e1","e2","e3"])");
  const Route plain = Route::readJson(dir / "plain.json");
  EXPECT_EQ(plain.sumo_edges.size(), 3u);
  Route r;
  r.planner = "postman";
  r.seed = 7;
  r.edges = {0, 1, 2};
  r.sumo_edges = {"a", "b"};
  r.length_m = 123.5;
  r.writeJson(dir / "r.json");
  const Route b = Route::readJson(dir / "r.json");
  EXPECT_EQ(b.planner, "postman");
  EXPECT_EQ(b.seed, 7u);
  EXPECT_EQ(b.edges, r.edges);
  EXPECT_DOUBLE_EQ(b.length_m, 123.5);
  r.writeRouXml(dir / "r.rou.xml");
  EXPECT_NE(readFile(dir / "r.rou.xml").find("edges=\"a b\""), std::string::npos);
  test::writeText(dir / "empty.json", "[]");
  EXPECT_THROW(Route::readJson(dir / "empty.json"), std::invalid_argument);
}

TEST(Scan, KittiRoundTripAndRings) {
  const auto dir = test::tempDir("scan");
  const LidarSpec spec = lidarPreset("paper");
  Scan s;
  // One point per ring at 20 m, at the ring's exact elevation.
  const double step = (spec.vfov_up_deg - spec.vfov_down_deg) / (spec.channels - 1);
  for (int r = 0; r < spec.channels; ++r) {
    const double el = (spec.vfov_down_deg + r * step) * M_PI / 180.0;
    s.points.push_back({static_cast<float>(20 * std::cos(el)), 0.f,
                        static_cast<float>(20 * std::sin(el)), 0.5f, r});
  }
  std::filesystem::create_directories(dir / "scans");
  writeKittiScan(dir / "scans" / "000000.bin", s);
  test::writeText(dir / "scans" / "times.txt", "0.0\n");
  KittiScanSource src(dir / "scans", spec);
  ASSERT_EQ(src.size(), 1u);
  const Scan back = src.scan(0);
  ASSERT_EQ(back.points.size(), s.points.size());
  for (std::size_t i = 0; i < s.points.size(); ++i)
    EXPECT_EQ(back.points[i].ring, s.points[i].ring);
  EXPECT_THROW(lidarPreset("nope"), std::invalid_argument);
  test::writeText(dir / "bad.bin", "abc");
  EXPECT_THROW(readKittiScan(dir / "bad.bin"), std::runtime_error);
}

struct Inner {
  double a_m = 1.5;
  std::string mode = "full";
};
template <class V>
void visitFields(V& v, Inner& c) {
  v.field("a_m", c.a_m, "a length [m]");
  v.field("mode", c.mode, "a mode");
}
struct Outer {
  int n = 3;
  bool on = true;
  Inner inner;
};
template <class V>
void visitFields(V& v, Outer& c) {
  v.field("n", c.n, "a count");
  v.field("on", c.on, "a switch");
  v.section("inner", c.inner);
}

TEST(ConfigIO, DumpLoadAndUnknownKeys) {
  Outer o;
  const std::string text = config::dumpYaml(o);
  EXPECT_NE(text.find("a_m: 1.5  # a length [m]"), std::string::npos) << text;
  Outer back;
  back.n = 99;
  config::loadYaml(YAML::Load(text), back, "dump");
  EXPECT_EQ(back.n, 3);  // the dump round-trips the defaults
  Outer part;
  config::loadYaml(YAML::Load("inner:\n  a_m: 7\n"), part, "x.yaml");
  EXPECT_DOUBLE_EQ(part.inner.a_m, 7.0);
  EXPECT_EQ(part.n, 3);  // only present keys change
  try {
    config::loadYaml(YAML::Load("inner:\n  a_mm: 7\n"), part, "x.yaml");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("x.yaml:inner: unknown key 'a_mm'"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(config::loadYaml(YAML::Load("n: lots\n"), part, "x.yaml"), std::invalid_argument);
}

TEST(AtomicFile, FailedWriteLeavesOldFileIntact) {
  const auto dir = test::tempDir("atomic");
  writeFileAtomic(dir / "f.txt", "old");
  {
    AtomicOutput out(dir / "f.txt");
    out.stream() << "half";
    // destroyed without commit, as when an exception unwinds
  }
  EXPECT_EQ(readFile(dir / "f.txt"), "old");
  std::size_t files = 0;
  for (auto& e : std::filesystem::directory_iterator(dir)) files += e.is_regular_file();
  EXPECT_EQ(files, 1u);  // no temp file left behind
}

}  // namespace
}  // namespace slamroute
