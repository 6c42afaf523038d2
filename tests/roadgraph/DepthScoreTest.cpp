// Depth-image spread score (paper §3.1 step 4, eqs. 3-4): known answers on rendered synthetic
// depth images, and the fallback for missing / corrupt frames.
#include <gtest/gtest.h>
#include "TestTmp.hpp"

#include <filesystem>
#include <fstream>

#include "slamroute/roadgraph/DepthScore.hpp"

namespace slamroute::roadgraph {
namespace {

namespace fs = std::filesystem;

struct Plane {
  Vec3 n;    ///< unit normal (camera frame: x right, y down, z forward)
  double d;  ///< n . X = d
};

/// Planar depth (mm) of the nearest plane hit by each pixel of an 800x600 pinhole camera
/// (90 degree horizontal field of view).
DepthImage render(const std::vector<Plane>& planes) {
  DepthImage img;
  img.width = 800;
  img.height = 600;
  img.mm.assign(800 * 600, 0);
  const double f = 400.0, cx = 399.5, cy = 299.5;
  for (int v = 0; v < 600; ++v)
    for (int u = 0; u < 800; ++u) {
      const Vec3 r((u - cx) / f, (v - cy) / f, 1.0);
      double best = 1e9;
      for (const auto& p : planes) {
        const double den = p.n.dot(r);
        if (std::abs(den) < 1e-9) continue;
        const double t = p.d / den;  // z of the hit (r has z = 1)
        if (t > 0.1 && t < best) best = t;
      }
      if (best < 60.0)
        img.mm[static_cast<std::size_t>(v) * 800 + u] = static_cast<std::uint16_t>(best * 1000.0);
    }
  return img;
}

TEST(DepthScore, FrontalPlaneScoresZero) {
  const auto s = scoreDepthImage(render({{Vec3(0, 0, 1), 10.0}}), DepthConfig{});
  EXPECT_GT(s.normals, 1000);
  EXPECT_LT(s.score, 0.05);
}

TEST(DepthScore, SinglePlaneScoresBelowThreePlaneCorner) {
  const DepthConfig cfg;
  // A wall seen obliquely (normal 30 degrees off the optical axis).
  const Vec3 n = Vec3(std::sin(0.5), 0, std::cos(0.5));
  const auto plane = scoreDepthImage(render({{n, 12.0}}), cfg);
  // Inside corner: floor 1.5 m below, left wall 3 m to the left, back wall 15 m ahead.
  const auto corner = scoreDepthImage(
      render({{Vec3(0, 1, 0), 1.5}, {Vec3(-1, 0, 0), 3.0}, {Vec3(0, 0, 1), 15.0}}), cfg);
  // Street canyon: floor and two side walls (normals spread over two directions only).
  const auto canyon = scoreDepthImage(
      render({{Vec3(0, 1, 0), 1.5}, {Vec3(-1, 0, 0), 6.0}, {Vec3(1, 0, 0), 6.0}}), cfg);
  EXPECT_LT(plane.score, 0.35) << plane.eigenvalues.transpose();
  EXPECT_GT(corner.score, 0.6) << corner.eigenvalues.transpose();
  EXPECT_LT(plane.score, corner.score);
  EXPECT_LT(plane.score, canyon.score);
  EXPECT_NEAR(corner.eigenvalues.sum(), 1.0, 1e-9);
}

TEST(DepthScore, EmptyImageScoresZeroAndDoesNotThrow) {
  DepthImage sky;
  sky.width = 80;
  sky.height = 60;
  sky.mm.assign(80 * 60, 0);
  const auto s = scoreDepthImage(sky, DepthConfig{});
  EXPECT_EQ(s.normals, 0);
  EXPECT_EQ(s.score, 0.0);
  DepthImage broken;
  broken.width = 10;
  broken.height = 10;
  EXPECT_THROW(scoreDepthImage(broken, DepthConfig{}), std::invalid_argument);
}

TEST(DepthScore, WeightsAreMeanFrameScoresWithFallbackForBadFrames) {
  const fs::path dir = slamroute::test::testTmp() / "roadgraph" / "depth";
  fs::create_directories(dir);
  const auto corner = render({{Vec3(0, 1, 0), 1.5}, {Vec3(-1, 0, 0), 3.0}, {Vec3(0, 0, 1), 15.0}});
  writeDepthPng(dir / "good.png", corner);
  std::ofstream(dir / "corrupt.png") << "this is not a png";
  // Graph: street 0 along x (two edges), street 1 along y.
  RoadGraph g;
  for (int i = 0; i < 3; ++i)
    g.nodes.push_back({i, Point3(i == 1 ? 100 : 0, i == 2 ? 100 : 0, 0), ""});
  g.edges.push_back({0, 0, 1, 100, 1, {Point3(0, 0, 0), Point3(100, 0, 0)}, {}, 0});
  g.edges.push_back({1, 1, 0, 100, 1, {Point3(100, 0, 0), Point3(0, 0, 0)}, {}, 0});
  g.edges.push_back({2, 0, 2, 100, 1, {Point3(0, 0, 0), Point3(0, 100, 0)}, {}, 1});
  std::vector<DepthFrame> frames(3);
  frames[0].pos = Point3(50, 2, 0);
  frames[0].file = dir / "good.png";
  frames[1].pos = Point3(2, 60, 0);
  frames[1].file = dir / "corrupt.png";
  frames[2].pos = Point3(2, 70, 0);
  frames[2].file = dir / "missing.png";
  WeightStats ws;
  ASSERT_NO_THROW(ws = assignDepthWeights(g, frames, DepthConfig{}));
  EXPECT_EQ(ws.scored, 1u);
  EXPECT_EQ(ws.failed, 2u);
  const double s = scoreDepthImage(corner, DepthConfig{}).score;
  EXPECT_DOUBLE_EQ(g.edges[0].weight, s);
  EXPECT_DOUBLE_EQ(g.edges[1].weight, s);
  EXPECT_DOUBLE_EQ(g.edges[2].weight, s);  // no usable frame: mean of all scored frames
  // Nothing usable at all: the configured fallback weight.
  frames.erase(frames.begin());
  DepthConfig cfg;
  cfg.fallback_weight = 1.0;
  assignDepthWeights(g, frames, cfg);
  for (const auto& e : g.edges) EXPECT_DOUBLE_EQ(e.weight, 1.0);
}

/// The first `w` x `h` pixels' worth of `img` (top-left corner), as a frame of that size.
DepthImage crop(const DepthImage& img, int w, int h) {
  DepthImage out;
  out.width = w;
  out.height = h;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) out.mm.push_back(img.at(x, y));
  return out;
}

TEST(DepthScore, FramesOfAnotherSizeAndFramesThatMeasureNothingAreNotUsed) {
  const fs::path dir = slamroute::test::testTmp() / "roadgraph" / "depth_sizes";
  fs::create_directories(dir);
  const auto corner = render({{Vec3(0, 1, 0), 1.5}, {Vec3(-1, 0, 0), 3.0}, {Vec3(0, 0, 1), 15.0}});
  writeDepthPng(dir / "a.png", corner);
  writeDepthPng(dir / "b.png", corner);
  writeDepthPng(dir / "small.png", crop(corner, 40, 30));  // a stray frame of another camera
  RoadGraph g;
  g.nodes = {{0, Point3(0, 0, 0), ""}, {1, Point3(100, 0, 0), ""}};
  g.edges.push_back({0, 0, 1, 100, 1, {Point3(0, 0, 0), Point3(100, 0, 0)}, {}, 0});
  std::vector<DepthFrame> frames(3);
  for (std::size_t i = 0; i < 3; ++i) frames[i].pos = Point3(10.0 + 30.0 * i, 2, 0);
  frames[0].file = dir / "a.png";
  frames[1].file = dir / "small.png";
  frames[2].file = dir / "b.png";
  const WeightStats ws = assignDepthWeights(g, frames, DepthConfig{});
  EXPECT_EQ(ws.scored, 2u);
  EXPECT_EQ(ws.failed, 1u);
  EXPECT_DOUBLE_EQ(g.edges[0].weight, scoreDepthImage(corner, DepthConfig{}).score);
  // Every frame 40 x 30 px where the survey's index says 800 x 600: none is used, every edge gets
  // the fallback weight (with a warning) instead of a weight near 0.
  for (const char* f : {"a.png", "b.png"}) writeDepthPng(dir / f, crop(corner, 40, 30));
  for (auto& fr : frames) {
    fr.width = 800;
    fr.height = 600;
  }
  DepthConfig cfg;
  cfg.fallback_weight = 0.7;
  const WeightStats tiny = assignDepthWeights(g, frames, cfg);
  EXPECT_EQ(tiny.scored, 0u);
  EXPECT_EQ(tiny.failed, 3u);
  EXPECT_DOUBLE_EQ(g.edges[0].weight, 0.7);
  // An index that says nothing of the size: the frames are used as they are.
  for (auto& fr : frames) fr.width = fr.height = 0;
  EXPECT_EQ(assignDepthWeights(g, frames, cfg).scored, 3u);
  // Every frame scores exactly 0 (a wall straight ahead in each): no information either.
  const auto wall = render({{Vec3(0, 0, 1), 10.0}});
  for (const char* f : {"a.png", "b.png", "small.png"}) writeDepthPng(dir / f, wall);
  EXPECT_EQ(assignDepthWeights(g, frames, cfg).scored, 0u);
  EXPECT_DOUBLE_EQ(g.edges[0].weight, 0.7);
}

TEST(DepthScore, PngRoundTripAndTruncatedFile) {
  const fs::path p = slamroute::test::testTmp() / "roadgraph" / "rt.png";
  fs::create_directories(p.parent_path());
  DepthImage img;
  img.width = 4;
  img.height = 3;
  img.mm = {0, 1, 2, 3, 1000, 2000, 3000, 4000, 65535, 7, 8, 9};
  writeDepthPng(p, img);
  const DepthImage back = readDepthPng(p);
  EXPECT_EQ(back.mm, img.mm);
  const auto size = fs::file_size(p);
  fs::resize_file(p, size / 2);
  EXPECT_THROW(readDepthPng(p), std::runtime_error);
  EXPECT_THROW(readDepthPng(p.parent_path() / "nope.png"), std::runtime_error);
}

}  // namespace
}  // namespace slamroute::roadgraph
