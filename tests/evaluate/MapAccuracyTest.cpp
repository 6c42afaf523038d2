// World mesh (PLY) reading, map-to-surface distances and the PCD writer.
#include "TestTmp.hpp"
#include <gtest/gtest.h>

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
  std::string s = "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\n"
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
  EXPECT_NEAR(a.p95_m, 0.3, 1e-6);
  EXPECT_EQ(a.points, 100);
  // beyond the edge of the square: distance to the edge, clamped at 2 m
  const MapAccuracy b = mapAccuracy({{11.0f, 0.0f, 0.0f}, {30.0f, 0.0f, 0.0f}}, mesh, 2.0);
  EXPECT_NEAR(b.mean_m, 1.5, 1e-6);
  EXPECT_NEAR(b.clamped_share, 0.5, 1e-12);
}

TEST(MapAccuracy, AsciiPlyAndBadFiles) {
  const fs::path p = tmpDir() / "tri.ply";
  std::ofstream(p) << "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                      "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                      "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  const Mesh m = readPly(p);
  EXPECT_EQ(m.faces.size(), 1u);
  EXPECT_THROW(readPly(tmpDir() / "nope.ply"), std::runtime_error);
  const fs::path bad = tmpDir() / "bad.ply";
  std::ofstream(bad) << "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nend_header\n1\n";
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
