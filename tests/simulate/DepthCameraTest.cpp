#include "TestTmp.hpp"
#include "slamroute/simulate/DepthCamera.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "WorldTestNet.hpp"

namespace slamroute::simulate {
namespace {

TEST(DepthCamera, PlaneAtKnownDistanceGivesThatDepthEverywhere) {
  const World w = World::fromMesh(testnet::wallAtX(20.0));
  const DepthCamera cam(DepthCameraConfig{}, 1);
  // body at the origin looking along +x; camera 0 m above it
  const DepthImage img = cam.render(w, DepthCamera::bodyToCamera(0.0));
  ASSERT_EQ(img.width, 800);
  ASSERT_EQ(img.height, 600);
  for (int v = 0; v < img.height; ++v)
    for (int u = 0; u < img.width; ++u) ASSERT_EQ(img.at(u, v), 20000) << u << "," << v;
  EXPECT_NEAR(cam.fx(), 400.0, 1e-9);  // 90 deg horizontal field
}

TEST(DepthCamera, FrameConventionXRightYDownZForward) {
  const World w = World::fromMesh(testnet::wallAtX(20.0));
  const DepthCamera cam(DepthCameraConfig{}, 1);
  // a tall box 14 m ahead whose front face spans 4..6 m to the right (world -y)
  VehicleBox b;
  b.x = 15, b.y = -5, b.z = -50, b.length = 2, b.width = 2, b.height = 100;
  const DepthImage img = cam.render(w, DepthCamera::bodyToCamera(0.0), {b});
  const int v = 300;
  const int u5 = static_cast<int>(std::lround(cam.cx() + cam.fx() * 5.0 / 14.0));
  const int ul = static_cast<int>(std::lround(cam.cx() - cam.fx() * 5.0 / 14.0));
  EXPECT_EQ(img.at(u5, v), 14000);
  EXPECT_EQ(img.at(ul, v), 20000);  // the mirror pixel (left) sees the wall
  EXPECT_EQ(img.at(400, v), 20000);
  // camera 1 m above the body, pitched down 10 deg: the centre pixel sees the wall lower
  const World floor_and_wall = World::fromMesh(testnet::wallAtX(20.0));
  const Pose3 T = DepthCamera::bodyToCamera(1.0, 10.0);
  const Vec3 fwd = T.linear() * Vec3::UnitZ();
  EXPECT_NEAR(fwd.x(), std::cos(10 * M_PI / 180), 1e-12);
  EXPECT_NEAR(fwd.z(), -std::sin(10 * M_PI / 180), 1e-12);
  EXPECT_NEAR((T.linear() * Vec3::UnitX()).y(), -1.0, 1e-12);  // camera x = body right = -y
  (void)floor_and_wall;
}

TEST(DepthCamera, NoReturnBeyondRangeIsZeroAndPngRoundTrips) {
  DepthCameraConfig c;
  c.width = 64;
  c.height = 48;
  c.max_range_m = 30.0;
  const DepthCamera cam(c);
  const World far = World::fromMesh(testnet::wallAtX(40.0));
  for (auto mm : cam.render(far, DepthCamera::bodyToCamera(0.0)).mm) ASSERT_EQ(mm, 0);
  const World w = World::fromMesh(testnet::room(10.0));
  Pose3 T = DepthCamera::bodyToCamera(0.0);
  T.translation() = Vec3(1, 2, 0.5);
  const DepthImage img = cam.render(w, T);
  const auto dir = slamroute::test::testTmp() / "depth";
  std::filesystem::create_directories(dir);
  writeDepthPng(dir / "d.png", img);
  const DepthImage back = readDepthPng(dir / "d.png");
  EXPECT_EQ(back.width, 64);
  EXPECT_EQ(back.height, 48);
  EXPECT_EQ(back.mm, img.mm);
  EXPECT_EQ(img.at(32, 24) > 0, true);
  EXPECT_THROW(readDepthPng(dir / "missing.png"), std::runtime_error);
}

TEST(DepthCamera, RejectsBadConfig) {
  DepthCameraConfig c;
  c.hfov_deg = 180;
  EXPECT_THROW(DepthCamera{c}, std::invalid_argument);
  c = DepthCameraConfig{};
  c.max_range_m = 100;
  EXPECT_THROW(DepthCamera{c}, std::invalid_argument);
}

}  // namespace
}  // namespace slamroute::simulate
