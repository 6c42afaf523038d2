#include "TestTmp.hpp"
#include "slamroute/simulate/Lidar.hpp"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <filesystem>

#include "WorldTestNet.hpp"

namespace slamroute::simulate {
namespace {

LidarConfig noiseFree(const std::string& preset = "paper") {
  LidarConfig c;
  c.preset = preset;
  c.range_sigma_m = 0.0;
  c.dropout_prob = 0.0;
  return c;
}

Pose3 at(double x, double y, double z, double yaw_deg = 0) {
  Pose3 T = Pose3::Identity();
  T.linear() = Eigen::AngleAxisd(yaw_deg * M_PI / 180.0, Vec3::UnitZ()).toRotationMatrix();
  T.translation() = Vec3(x, y, z);
  return T;
}

TEST(Lidar, RayToPlaneAtKnownDistance) {
  const World w = World::fromMesh(testnet::wallAtX(20.0));
  const Lidar lidar(noiseFree(), 1);
  const Scan s = lidar.scan(w, Pose3::Identity(), {}, 0);
  ASSERT_FALSE(s.points.empty());
  std::size_t forward = 0;
  for (const auto& p : s.points) {
    EXPECT_NEAR(p.x, 20.0, 2e-3) << "ring " << p.ring;  // every return lies on the wall
    if (std::abs(p.y) < 1e-3) {
      ++forward;  // column 0: range = 20 / cos(elevation)
      const double el = lidar.elevationRad(p.ring);
      EXPECT_NEAR(std::sqrt(p.x * p.x + p.z * p.z), 20.0 / std::cos(el), 2e-3);
    }
  }
  EXPECT_EQ(forward, 64u);
  // intensity: reflectivity x cos(incidence); straight on (ring of elevation ~0) is the largest
  for (const auto& p : s.points) {
    EXPECT_GT(p.intensity, 0.0f);
    EXPECT_LE(p.intensity, 1.0f);
  }
}

TEST(Lidar, PoseRotatesTheScene) {
  const World w = World::fromMesh(testnet::wallAtX(20.0));
  const Lidar lidar(noiseFree(), 1);
  // sensor at x = 5 yawed +90 deg: the wall (world +x, 15 m away) is on the sensor's right (-y)
  const Scan s = lidar.scan(w, at(5, 0, 0, 90), {}, 0);
  ASSERT_FALSE(s.points.empty());
  for (const auto& p : s.points) EXPECT_NEAR(p.y, -15.0, 2e-3);
}

TEST(Lidar, BoxAppearsWhereItShouldWithTheRightExtent) {
  const World w = World::fromMesh(TriangleMesh{});
  const Lidar lidar(noiseFree(), 1);
  VehicleBox car;
  car.x = 10, car.y = 0, car.z = 0, car.heading_deg = 0, car.length = 4, car.width = 2,
  car.height = 1.5;
  const Scan s = lidar.scan(w, at(0, 0, 1.8), {car}, 0);
  ASSERT_GT(s.points.size(), 20u);
  double xmin = 1e9, ymin = 1e9, ymax = -1e9, zmin = 1e9, zmax = -1e9;
  for (const auto& p : s.points) {
    xmin = std::min<double>(xmin, p.x);
    ymin = std::min<double>(ymin, p.y);
    ymax = std::max<double>(ymax, p.y);
    zmin = std::min<double>(zmin, p.z);
    zmax = std::max<double>(zmax, p.z);
    EXPECT_GE(p.x, 8.0 - 1e-3);
    EXPECT_LE(p.x, 12.0 + 1e-3);
    EXPECT_LE(std::abs(p.y), 1.0 + 1e-3);
    EXPECT_GE(p.z, -1.8 - 1e-3);
    EXPECT_LE(p.z, -0.3 + 1e-3);
  }
  EXPECT_NEAR(xmin, 8.0, 1e-3);  // the front face
  EXPECT_LT(ymin, -0.9);         // the full width is seen
  EXPECT_GT(ymax, 0.9);
  EXPECT_NEAR(zmax, -0.3, 0.15);  // roof at 1.5 m = -0.3 in the sensor frame
  // turned 90 deg, the front face is 1 m (half width) from the centre, the extent 4 m
  car.heading_deg = 90;
  const Scan t = lidar.scan(w, at(0, 0, 1.8), {car}, 0);
  double xmin2 = 1e9, ymax2 = 0;
  for (const auto& p : t.points) {
    xmin2 = std::min<double>(xmin2, p.x);
    ymax2 = std::max<double>(ymax2, std::abs(p.y));
  }
  EXPECT_NEAR(xmin2, 9.0, 1e-3);
  EXPECT_GT(ymax2, 1.5);
  EXPECT_LE(ymax2, 2.0 + 1e-3);
  // a box behind a wall is hidden
  const World wall = World::fromMesh(testnet::wallAtX(5.0));
  for (const auto& p : lidar.scan(wall, at(0, 0, 1.8), {car}, 0).points)
    EXPECT_NEAR(p.x, 5.0, 2e-3);
}

TEST(Lidar, RingIndicesAndVerticalAnglesMatchTheSpec) {
  const World w = World::fromMesh(testnet::room(50.0));
  for (const std::string preset : {"paper", "vlp16", "hdl32"}) {
    const Lidar lidar(noiseFree(preset), 1);
    const LidarSpec spec = lidarPreset(preset);
    const Scan s = lidar.scan(w, Pose3::Identity(), {}, 0);
    ASSERT_EQ(s.points.size(), static_cast<std::size_t>(spec.channels * spec.horizontal_samples))
        << preset;
    std::vector<int> per_ring(static_cast<std::size_t>(spec.channels), 0);
    for (std::size_t i = 0; i < s.points.size(); ++i) {
      const auto& p = s.points[i];
      ASSERT_GE(p.ring, 0);
      ASSERT_LT(p.ring, spec.channels);
      ++per_ring[static_cast<std::size_t>(p.ring)];
      const double el = std::atan2(p.z, std::hypot(p.x, p.y)) * 180.0 / M_PI;
      const double want = spec.vfov_down_deg +
                          (spec.vfov_up_deg - spec.vfov_down_deg) * p.ring / (spec.channels - 1);
      ASSERT_NEAR(el, want, 1e-3) << preset << " ring " << p.ring;
      ASSERT_EQ(ringFromElevation(spec, p.x, p.y, p.z), p.ring);
      // order: column-major, rings ascending within a column
      ASSERT_EQ(p.ring, static_cast<int>(i % static_cast<std::size_t>(spec.channels)));
    }
    for (int n : per_ring) EXPECT_EQ(n, spec.horizontal_samples);
    EXPECT_NEAR(lidar.elevationRad(0) * 180 / M_PI, spec.vfov_down_deg, 1e-9);
    EXPECT_NEAR(lidar.elevationRad(spec.channels - 1) * 180 / M_PI, spec.vfov_up_deg, 1e-9);
  }
}

TEST(Lidar, RangeLimitsDropReturns) {
  const Lidar lidar(noiseFree(), 1);
  EXPECT_TRUE(lidar.scan(World::fromMesh(testnet::wallAtX(100.5)), Pose3::Identity(), {}, 0)
                  .points.empty());
  // a wall 0.5 m away: only returns farther than min_range (1 m) survive, i.e. oblique beams
  const Scan near = lidar.scan(World::fromMesh(testnet::wallAtX(0.5)), Pose3::Identity(), {}, 0);
  ASSERT_FALSE(near.points.empty());
  for (const auto& p : near.points) {
    EXPECT_GE(std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z), 1.0 - 1e-4);
    EXPECT_GT(std::abs(p.y) + std::abs(p.z), 0.5);  // never the straight-ahead beams
  }
}

TEST(Lidar, NoiseAndDropoutAreDeterministicPerSeedAndScan) {
  const World w = World::fromMesh(testnet::room(30.0));
  LidarConfig c = noiseFree();
  c.range_sigma_m = 0.05;
  c.dropout_prob = 0.1;
  const Lidar a(c, 9), b(c, 9), other(c, 10);
  const Scan s1 = a.scan(w, Pose3::Identity(), {}, 3);
  Scan s2;
  {
    tbb::task_arena one(1);  // thread count does not matter
    one.execute([&] { s2 = b.scan(w, Pose3::Identity(), {}, 3); });
  }
  ASSERT_EQ(s1.points.size(), s2.points.size());
  for (std::size_t i = 0; i < s1.points.size(); ++i) {
    ASSERT_EQ(s1.points[i].x, s2.points[i].x);
    ASSERT_EQ(s1.points[i].y, s2.points[i].y);
    ASSERT_EQ(s1.points[i].z, s2.points[i].z);
    ASSERT_EQ(s1.points[i].intensity, s2.points[i].intensity);
  }
  const Scan s3 = a.scan(w, Pose3::Identity(), {}, 4), s4 = other.scan(w, Pose3::Identity(), {}, 3);
  EXPECT_NE(s1.points.front().x, s3.points.front().x);
  EXPECT_NE(s1.points.front().x, s4.points.front().x);
  // dropout share and range noise statistics (fixed seed, so these are exact checks of a known
  // draw)
  const double n_all = 64.0 * 1800.0;
  EXPECT_NEAR(s1.points.size() / n_all, 0.9, 0.01);
  const World wall = World::fromMesh(testnet::wallAtX(20.0));
  const Scan sw = a.scan(wall, Pose3::Identity(), {}, 0);
  double sum = 0, sum2 = 0;
  std::size_t n = 0;
  for (const auto& p : sw.points) {
    const double r = std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
    const double r_true = r * 20.0 / p.x;  // the direction is exact; only the range is noisy
    const double e = r - r_true;
    (void)e;
    const double along = (p.x - 20.0) * r / p.x;  // range error along the beam
    sum += along;
    sum2 += along * along;
    ++n;
  }
  ASSERT_GT(n, 1000u);
  EXPECT_NEAR(sum / n, 0.0, 0.005);
  EXPECT_NEAR(std::sqrt(sum2 / n), 0.05, 0.005);
  // scanMany == scan
  const auto many = a.scanMany(w, {Pose3::Identity(), Pose3::Identity()},
                               {Pose3::Identity(), Pose3::Identity()}, {}, 3, {1.0, 2.0});
  ASSERT_EQ(many.size(), 2u);
  ASSERT_EQ(many[0].points.size(), s1.points.size());
  EXPECT_EQ(many[0].points[100].x, s1.points[100].x);
  EXPECT_EQ(many[0].t, 1.0);
}

TEST(Lidar, OverpassAppearsAsADeckAboveTheStreet) {
  // synthetic overpass: the S->N road is a deck at z = 7 (1 m thick) over the W-E street
  const World w = World::build(testnet::overpassNet(), WorldConfig{}, 3);
  const Lidar lidar(noiseFree(), 1);
  // on the W->E lane, 30 m before the bridge (with +10 deg up, the deck 4 m above the sensor is
  // in view from ~24 m on), facing it
  const Pose3 T = at(-30, -1.6, 1.8);
  const Scan s = lidar.scan(w, T, {}, 0);
  std::size_t deck = 0, street_ahead = 0;
  for (const auto& p : s.points) {
    const Vec3 q = T * Vec3(p.x, p.y, p.z);
    // the deck's side (z 6..7) and its parapet (7..8), right above the street (|y| < 5)
    if (std::abs(q.x()) < 3.6 && std::abs(q.y()) < 5 && q.z() > 5.95 && q.z() < 8.05) ++deck;
    if (q.x() > 5 && q.x() < 40 && std::abs(q.y() + 1.6) < 1.5 && std::abs(q.z()) < 0.05)
      ++street_ahead;
  }
  EXPECT_GT(deck, 20u);          // the deck, above the street
  EXPECT_GT(street_ahead, 10u);  // and the street continues beyond it, unblocked
}

TEST(Lidar, ShippedOverpassAppearsAsADeckAboveTheStreet) {
  const auto net_path =
      std::filesystem::path(SLAMROUTE_SOURCE_DIR) / "networks/test/overpass.net.xml";
  ASSERT_TRUE(std::filesystem::exists(net_path)) << net_path << " missing";
  const SumoNet net = SumoNet::read(net_path);
  const World w = World::build(net, WorldConfig{}, 42);
  const Lidar lidar(noiseFree(), 1);
  // on W_E (y = 498.4 for the eastbound lane), 30 m before the S_N deck at x = 500 (z = 6)
  const double y = net.findEdge("W_E")->lanes.front().shape.front().y();
  const Pose3 T = at(470, y, 1.8);
  std::size_t deck = 0;
  for (const auto& p : lidar.scan(w, T, {}, 0).points) {
    const Vec3 q = T * Vec3(p.x, p.y, p.z);
    if (std::abs(q.x() - 500) < 4 && std::abs(q.y() - 500) < 6 && q.z() > 4.95 && q.z() < 7.05)
      ++deck;
  }
  EXPECT_GT(deck, 20u);
}

TEST(Lidar, MovingSensorFiresEachColumnAtItsOwnTimeAndPose) {
  // 14 m/s sideways and turning 6 deg within the sweep, in front of the wall x = 20
  const World w = World::fromMesh(testnet::wallAtX(20.0));
  const Lidar lidar(noiseFree("vlp16"), 1);
  const Pose3 start = at(0, 0, 1.8, 0), end = at(0, 1.4, 1.8, 6);
  const Scan s = lidar.scan(w, start, end, {}, 0, 5.0);
  ASSERT_TRUE(s.has_point_times);
  ASSERT_GT(s.points.size(), 1000u);
  float last = 0, lo = 1, hi = 0;
  std::size_t off_unless_deskewed = 0;
  for (const auto& p : s.points) {
    ASSERT_GE(p.dt, last);  // column order is firing order
    last = p.dt;
    lo = std::min(lo, p.dt);
    hi = std::max(hi, p.dt);
    // deskew with the known motion: the pose at the point's own firing time
    const double f = p.dt / 0.1;
    const Pose3 T = at(0, 1.4 * f, 1.8, 6 * f);
    const Vec3 q = T * Vec3(p.x, p.y, p.z);
    ASSERT_NEAR(q.x(), 20.0, 2e-3) << "dt " << p.dt;
    if (std::abs((start * Vec3(p.x, p.y, p.z)).x() - 20.0) > 0.05) ++off_unless_deskewed;
  }
  EXPECT_LT(lo, 1e-3);
  EXPECT_GT(hi, 0.09);
  EXPECT_LT(hi, 0.1);
  EXPECT_GT(off_unless_deskewed, s.points.size() / 4);  // the raw scan is distorted
  // the KITTI files keep the point times
  const auto dir = slamroute::test::testTmp() / "lidar_times";
  std::filesystem::create_directories(dir);
  writeKittiScan(dir / "000000.bin", s);
  const Scan r = readKittiScan(dir / "000000.bin");
  ASSERT_TRUE(r.has_point_times);
  ASSERT_EQ(r.points.size(), s.points.size());
  for (std::size_t i = 0; i < r.points.size(); ++i) ASSERT_EQ(r.points[i].dt, s.points[i].dt);
  // switched off: one pose for the whole sweep, no times
  LidarConfig still = noiseFree("vlp16");
  still.motion_distortion = false;
  const Scan t = Lidar(still, 1).scan(w, start, end, {}, 0, 5.0);
  EXPECT_FALSE(t.has_point_times);
  for (const auto& p : t.points) ASSERT_NEAR((start * Vec3(p.x, p.y, p.z)).x(), 20.0, 2e-3);
}

TEST(Lidar, PresetsAndOverrides) {
  LidarConfig c;
  c.preset = "vlp16";
  EXPECT_EQ(resolveLidarSpec(c).channels, 16);
  c.spec.horizontal_samples = 900;  // differs from the default: overrides the preset
  EXPECT_EQ(resolveLidarSpec(c).horizontal_samples, 900);
  EXPECT_EQ(resolveLidarSpec(c).channels, 16);
  // resolving a resolved spec again gives the same spec (sensor.yaml round trip)
  LidarConfig r = c;
  r.spec = resolveLidarSpec(c);
  EXPECT_EQ(resolveLidarSpec(r).channels, 16);
  EXPECT_EQ(resolveLidarSpec(r).vfov_up_deg, 15.0);
  c.preset = "hdl99";
  EXPECT_THROW(resolveLidarSpec(c), std::invalid_argument);
  LidarConfig bad;
  bad.dropout_prob = 1.5;
  EXPECT_THROW(Lidar(bad, 1), std::invalid_argument);
  bad = LidarConfig{};
  bad.spec.vfov_up_deg = -40;
  EXPECT_THROW(Lidar(bad, 1), std::invalid_argument);
}

}  // namespace
}  // namespace slamroute::simulate
