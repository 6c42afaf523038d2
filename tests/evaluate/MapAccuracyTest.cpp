// World mesh (PLY) reading, map-to-surface distances and the PCD writer.
#include <gtest/gtest.h>
#include "TestTmp.hpp"

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "slamroute/core/AtomicFile.hpp"
#include "slamroute/evaluate/MapAccuracy.hpp"
#include "slamroute/evaluate/Output.hpp"

namespace slamroute::evaluate {
namespace {
namespace fs = std::filesystem;

fs::path tmpDir() {
  fs::path d = slamroute::test::testTmp() / "evaluate_map";
  fs::create_directories(d);
  return d;
}

/// A 20 x 20 m square at z = 0 as two triangles, binary little-endian PLY.
void writeSquarePly(const fs::path& p) {
  std::string s =
      "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\n"
      "property float y\nproperty float z\nelement face 1\n"
      "property list uchar int vertex_indices\nend_header\n";
  const float v[12] = {-10, -10, 0, 10, -10, 0, 10, 10, 0, -10, 10, 0};
  s.append(reinterpret_cast<const char*>(v), sizeof(v));
  s.push_back(4);  // one quad, fanned into two triangles
  const int f[4] = {0, 1, 2, 3};
  s.append(reinterpret_cast<const char*>(f), sizeof(f));
  std::ofstream(p, std::ios::binary) << s;
}

TEST(MapAccuracy, DistancesToAPlane) {
  const fs::path p = tmpDir() / "square.ply";
  writeSquarePly(p);
  const Mesh mesh = readPly(p);
  ASSERT_EQ(mesh.vertices.size(), 4u);
  ASSERT_EQ(mesh.faces.size(), 2u);
  Cloud map;
  for (int i = 0; i < 100; ++i) map.push_back({-5.0f + 0.1f * i, 1.0f, i < 50 ? 0.1f : -0.3f});
  const MapAccuracy a = mapAccuracy(map, mesh, 2.0);
  EXPECT_NEAR(a.mean_m, 0.2, 1e-6);
  EXPECT_NEAR(a.p95_m, 0.3, 1e-4);  // quantiles to a 0.1 mm bin
  EXPECT_EQ(a.points, 100);
  // beyond the edge of the square: distance to the edge, clamped at 2 m
  const MapAccuracy b = mapAccuracy({{11.0f, 0.0f, 0.0f}, {30.0f, 0.0f, 0.0f}}, mesh, 2.0);
  EXPECT_NEAR(b.mean_m, 1.5, 1e-6);
  EXPECT_NEAR(b.clamped_share, 0.5, 1e-12);
  EXPECT_EQ(b.median_m, 2.0);  // the upper of the two: clamped, so the clamp exactly
}

TEST(MapAccuracy, PartByPartGivesTheSameAsTheWholeMap) {
  const fs::path p = tmpDir() / "square_parts.ply";
  writeSquarePly(p);
  const Mesh mesh = readPly(p);
  Cloud map;
  for (int i = 0; i < 300; ++i)
    map.push_back({-12.0f + 0.08f * static_cast<float>(i),
                   0.05f * static_cast<float>(i % 40) - 1.0f,
                   0.01f * static_cast<float>(i % 37) - 0.1f});
  const MapAccuracy whole = mapAccuracy(map, mesh, 2.0);
  Eigen::AlignedBox3f bounds;
  for (const auto& q : map) bounds.extend(q);
  MapAccuracyMeter meter(mesh, 2.0, bounds);
  for (std::size_t a = 0; a < map.size(); a += 70)
    meter.add(Cloud(map.begin() + static_cast<std::ptrdiff_t>(a),
                    map.begin() + static_cast<std::ptrdiff_t>(std::min(map.size(), a + 70))));
  const MapAccuracy parts = meter.result();
  EXPECT_EQ(parts.points, 300);
  EXPECT_NEAR(parts.mean_m, whole.mean_m, 1e-12);
  EXPECT_EQ(parts.median_m, whole.median_m);
  EXPECT_EQ(parts.p95_m, whole.p95_m);
  EXPECT_EQ(parts.clamped_share, whole.clamped_share);
  EXPECT_GT(whole.clamped_share, 0.0);  // points beyond x = 12 m are off the square
  // A point outside the bounds the meter was made for counts as far (clamped).
  MapAccuracyMeter small(
      mesh, 2.0, Eigen::AlignedBox3f(Eigen::Vector3f(-1, -1, -1), Eigen::Vector3f(1, 1, 1)));
  small.add({{0.0f, 0.0f, 0.5f}, {8.0f, 8.0f, 0.0f}});
  const MapAccuracy s = small.result();
  EXPECT_NEAR(s.mean_m, (0.5 + 2.0) / 2.0, 1e-6);
  EXPECT_NEAR(s.clamped_share, 0.5, 1e-12);
}

TEST(Output, MapErrorImageShowsWhereTheMapIsOff) {
  // West half of a 100 m square 0.1 m off, east half 1.5 m off; each pixel shows its mean.
  const Eigen::AlignedBox3f bounds(Eigen::Vector3f(0, 0, 0), Eigen::Vector3f(100, 100, 5));
  MapErrorImage img(bounds, 400);
  Cloud west, east;
  std::vector<float> dw, de;
  for (int i = 0; i < 50; ++i)
    for (int k = 0; k < 100; ++k) {
      west.push_back({0.5f + static_cast<float>(i), 0.5f + static_cast<float>(k), 1.0f});
      dw.push_back(0.1f);
      east.push_back({50.5f + static_cast<float>(i), 0.5f + static_cast<float>(k), 1.0f});
      de.push_back(k % 2 ? 1.0f : 2.0f);  // two points per pixel on average: mean 1.5
    }
  img.add(west, dw.data());
  img.add(east, de.data());
  EXPECT_NEAR(img.meanAt(20.5, 40.5), 0.1, 1e-6);
  EXPECT_NEAR(img.meanAt(70.5, 40.5), 1.5, 0.51);
  EXPECT_TRUE(std::isnan(img.meanAt(500.0, 40.0)));  // off the image
  const fs::path png = tmpDir() / "map_error_top.png";
  img.write(png, "test", 2.0);
  EXPECT_EQ(readFile(png).substr(1, 3), "PNG");
  EXPECT_THROW(img.write(png, "test", 0.0), std::invalid_argument);
  MapErrorImage empty(Eigen::AlignedBox3f(), 400);  // no map: a blank image, no error
  empty.add(west, dw.data());
  EXPECT_TRUE(std::isnan(empty.meanAt(20.5, 40.5)));
  EXPECT_NO_THROW(empty.write(tmpDir() / "empty_map.png", "no map", 1.0));
}

TEST(Output, TopViewFrameCentresTheBox) {
  // A 1000 m x 100 m box in 1000 px with 40 px margins: 0.92 px/m, the long side from margin to
  // margin, the short side centred (not at the bottom edge).
  const TopViewFrame f({0.0, 0.0}, {1000.0, 100.0}, 1000, 40);
  EXPECT_DOUBLE_EQ(f.scale, 0.92);
  EXPECT_TRUE(f.pixel(500.0, 50.0).isApprox(Eigen::Vector2d(500.0, 500.0)));
  EXPECT_NEAR(f.pixel(0.0, 50.0).x(), 40.0, 1e-9);
  EXPECT_NEAR(f.pixel(1000.0, 50.0).x(), 960.0, 1e-9);
  EXPECT_NEAR(f.pixel(500.0, 0.0).y(), 546.0, 1e-9);  // south is down
  EXPECT_NEAR(f.pixel(500.0, 100.0).y(), 454.0, 1e-9);
  const TopViewFrame dot({5.0, 5.0}, {5.0, 5.0}, 400, 40);  // a single point: 1 m spans the image
  EXPECT_DOUBLE_EQ(dot.scale, 320.0);
  EXPECT_TRUE(dot.pixel(5.0, 5.0).isApprox(Eigen::Vector2d(200.0, 200.0)));
}

TEST(Output, PcdWriterGivesTheFileWritePcdGives) {
  const Cloud a{{1.0f, 2.0f, 3.0f}, {4.0f, 5.0f, 6.0f}}, b{{-7.5f, 8.25f, 9.0f}};
  Cloud ab = a;
  ab.insert(ab.end(), b.begin(), b.end());
  const fs::path dir = tmpDir() / "pcd_writer";
  fs::remove_all(dir);
  fs::create_directories(dir);
  writePcd(dir / "whole.pcd", ab);
  {
    PcdWriter w(dir / "parts.pcd");
    w.add(a);
    w.add({});
    w.add(b);
    EXPECT_EQ(w.points(), 3u);
    EXPECT_FALSE(fs::exists(dir / "parts.pcd"));  // only at commit
    w.commit();
  }
  EXPECT_EQ(readFile(dir / "parts.pcd"), readFile(dir / "whole.pcd"));
  {
    PcdWriter w(dir / "empty.pcd");
    w.commit();
  }
  EXPECT_NE(readFile(dir / "empty.pcd").find("POINTS 0\nDATA binary\n"), std::string::npos);
  {
    PcdWriter abandoned(dir / "abandoned.pcd");
    abandoned.add(a);
  }
  int files = 0;
  for (const auto& e : fs::directory_iterator(dir)) {
    ++files;
    EXPECT_NE(e.path().filename(), "abandoned.pcd");
  }
  EXPECT_EQ(files, 3);  // whole, parts, empty: nothing half-written left
  EXPECT_THROW(PcdWriter(dir / "no" / "such" / "folder.pcd"), std::runtime_error);
}

TEST(MapAccuracy, AsciiPlyAndBadFiles) {
  const fs::path p = tmpDir() / "tri.ply";
  std::ofstream(p)
      << "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
         "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
         "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  const Mesh m = readPly(p);
  EXPECT_EQ(m.faces.size(), 1u);
  EXPECT_THROW(readPly(tmpDir() / "nope.ply"), std::runtime_error);
  const fs::path bad = tmpDir() / "bad.ply";
  std::ofstream(bad)
      << "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nend_header\n1\n";
  EXPECT_THROW(readPly(bad), std::runtime_error);
}

TEST(Output, PcdIsBinaryXyz) {
  const fs::path p = tmpDir() / "map.pcd";
  writePcd(p, {{1.0f, 2.0f, 3.0f}, {4.0f, 5.0f, 6.0f}});
  const std::string s = readFile(p);
  const auto pos = s.find("DATA binary\n");
  ASSERT_NE(pos, std::string::npos);
  EXPECT_NE(s.find("POINTS 2\n"), std::string::npos);
  const std::string data = s.substr(pos + 12);
  ASSERT_EQ(data.size(), 24u);
  float v[6];
  std::memcpy(v, data.data(), 24);
  EXPECT_EQ(v[5], 6.0f);
}

}  // namespace
}  // namespace slamroute::evaluate
