// MapOutput: the map streamed into map.pcd and measured against the world mesh as built and
// after the estimate's alignment onto the ground truth.
#include <gtest/gtest.h>
#include "TestTmp.hpp"

#include <filesystem>
#include <fstream>

#include "slamroute/core/AtomicFile.hpp"
#include "slamroute/evaluate/MapOutput.hpp"

namespace slamroute::evaluate {
namespace {
namespace fs = std::filesystem;

/// The ground: a 200 x 200 m square at z = 0 (two triangles).
Mesh ground() {
  Mesh m;
  m.vertices = {{-100, -100, 0}, {100, -100, 0}, {100, 100, 0}, {-100, 100, 0}};
  m.faces = {{0, 1, 2}, {0, 2, 3}};
  return m;
}

/// A square drive of 40 m sides at z = 0, one pose a second; `lift` raises every pose.
Trajectory squareDrive(double lift) {
  Trajectory t;
  for (int i = 0; i < 160; ++i) {
    const int side = i / 40, s = i % 40;
    const double x = side == 0 ? s : side == 1 ? 40 : side == 2 ? 40 - s : 0;
    const double y = side == 0 ? 0 : side == 1 ? s : side == 2 ? 40 : 40 - s;
    StampedPose p;
    p.t = i;
    p.T_world_body.translation() = Vec3(x, y, lift);
    t.push_back(p);
  }
  return t;
}

TEST(MapOutput, AlignedAccuracyRemovesWhereTheEstimateStartedDrifting) {
  // The estimate (and the map built on it) is 0.5 m too high everywhere: as built, every ground
  // point is 0.5 m off; aligned like the ATE (T_gt_est lowers it by 0.5 m), none is.
  const fs::path dir = slamroute::test::testTmp() / "map_output";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const Mesh mesh = ground();
  const Trajectory gt = squareDrive(0.0), est = squareDrive(0.5);
  MapOutput out(dir / "map.pcd", &mesh, &gt, 0.02, 2.0, 300);
  Cloud tile1, tile2;
  for (int i = 0; i < 50; ++i)
    for (int k = 0; k < 50; ++k) (i < 25 ? tile1 : tile2).push_back({0.8f * i, 0.8f * k, 0.5f});
  Eigen::AlignedBox3f bounds;
  for (const auto& p : tile1) bounds.extend(p);
  for (const auto& p : tile2) bounds.extend(p);
  out.estimate(est);
  EXPECT_NEAR(out.alignment().translation().z(), -0.5, 1e-9);
  out.begin(bounds);
  out.add(tile1);
  out.add(tile2);
  out.commit();
  const MapAccuracy built = *out.accuracy(), aligned = *out.alignedAccuracy();
  EXPECT_EQ(built.points, 2500);
  EXPECT_NEAR(built.median_m, 0.5, 1e-4);  // quantiles to a 0.1 mm bin
  EXPECT_NEAR(built.mean_m, 0.5, 1e-6);
  EXPECT_EQ(aligned.points, 2500);
  EXPECT_NEAR(aligned.median_m, 0.0, 1e-4);
  EXPECT_NEAR(aligned.p95_m, 0.0, 1e-4);
  out.writeImage(dir / "map_error_top.png");
  EXPECT_TRUE(fs::exists(dir / "map_error_top.png"));
  EXPECT_NE(readFile(dir / "map.pcd").find("POINTS 2500\n"), std::string::npos);
}

TEST(MapOutput, WithoutAMeshOnlyThePcd) {
  const fs::path dir = slamroute::test::testTmp() / "map_output_nomesh";
  fs::remove_all(dir);
  fs::create_directories(dir);
  MapOutput out(dir / "map.pcd", nullptr, nullptr, 0.02, 2.0, 300);
  out.estimate(squareDrive(0.0));
  out.begin(Eigen::AlignedBox3f(Eigen::Vector3f::Zero(), Eigen::Vector3f::Ones()));
  out.add({{0.5f, 0.5f, 0.5f}});
  out.commit();
  EXPECT_FALSE(out.accuracy());
  EXPECT_FALSE(out.alignedAccuracy());
  out.writeImage(dir / "none.png");
  EXPECT_FALSE(fs::exists(dir / "none.png"));
  EXPECT_NE(readFile(dir / "map.pcd").find("POINTS 1\n"), std::string::npos);
}

}  // namespace
}  // namespace slamroute::evaluate
