// The SLAM map built tile by tile (MapTiles.hpp) must hold exactly the points voxelFilter gives
// for every keyframe's cloud at its pose joined: same voxels, same float sums, tile by tile.
#include <gtest/gtest.h>
#include "TestTmp.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <random>

#include "slamroute/evaluate/MapTiles.hpp"

namespace slamroute::evaluate {
namespace {

struct Drive {
  std::vector<Cloud> clouds;  ///< body frame
  std::vector<Pose3> poses;
};

/// Keyframes along a wandering path through negative and positive coordinates, clouds of up to
/// 30 m around them, some points exactly on multiples of the tile size.
Drive randomDrive(unsigned seed, int keyframes) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-30.0f, 30.0f);
  std::uniform_real_distribution<double> yaw(-3.1, 3.1);
  Drive d;
  Eigen::Vector3d at(-70.0, -40.0, 0.0);
  for (int k = 0; k < keyframes; ++k) {
    Cloud c;
    for (int i = 0; i < 400; ++i) c.emplace_back(u(rng), u(rng), 0.1f * u(rng));
    c.emplace_back(25.0f, -50.0f, 0.0f);
    d.clouds.push_back(c);
    Pose3 T = Pose3::Identity();
    T.linear() = Eigen::AngleAxisd(yaw(rng), Eigen::Vector3d::UnitZ()).toRotationMatrix();
    T.translation() = at;
    d.poses.push_back(T);
    at += Eigen::Vector3d(std::cos(0.3 * k), std::sin(0.2 * k), 0.0) * 12.0;
  }
  return d;
}

Cloud joined(const Drive& d) {
  Cloud all;
  for (std::size_t k = 0; k < d.clouds.size(); ++k) {
    const Cloud c = transformed(d.clouds[k], d.poses[k]);
    all.insert(all.end(), c.begin(), c.end());
  }
  return all;
}

std::vector<MapKeyframe> store(const Drive& d, CloudStore& clouds) {
  std::vector<MapKeyframe> kfs;
  for (std::size_t k = 0; k < d.clouds.size(); ++k)
    kfs.push_back({clouds.add(d.clouds[k]), d.poses[k]});
  return kfs;
}

/// Points ordered by their bits, to compare two maps as sets of exact floats.
Cloud sortedBits(Cloud c) {
  std::sort(c.begin(), c.end(), [](const Eigen::Vector3f& a, const Eigen::Vector3f& b) {
    return std::memcmp(a.data(), b.data(), sizeof(Eigen::Vector3f)) < 0;
  });
  return c;
}

void expectBitEqual(const Cloud& a, const Cloud& b) {
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(Eigen::Vector3f)), 0);
}

/// Records the parts and the bounds it is given.
class PartsSink : public MapSink {
 public:
  void begin(const Eigen::AlignedBox3f& b) override {
    ++begins;
    bounds = b;
  }
  void add(const Cloud& part) override { parts.push_back(part); }
  int begins = 0;
  Eigen::AlignedBox3f bounds;
  std::vector<Cloud> parts;
};

TEST(MapTiles, TilesHoldExactlyTheVoxelFilterOfAllCloudsJoined) {
  const Drive d = randomDrive(5, 30);
  const Cloud want = voxelFilter(joined(d), 0.5);
  ASSERT_GT(want.size(), 1000u);
  for (double tile : {4.0, 4.3, 25.0, 60.0}) {  // 4.3: rounded to 9 voxels
    CloudStore clouds;
    const auto kfs = store(d, clouds);
    PartsSink sink;
    const std::size_t points = buildMapByTiles(clouds, kfs, 0.5, tile, sink);
    EXPECT_EQ(points, want.size());
    EXPECT_EQ(sink.begins, 1);
    EXPECT_GT(sink.parts.size(), 4u) << "tile " << tile;
    Cloud got;
    const auto per_tile = static_cast<std::int64_t>(std::llround(tile / 0.5));  // whole voxels
    const auto tileOf = [&](float v) {
      return static_cast<std::int64_t>(
          std::floor(static_cast<double>(voxelIndex(v, 2.0f)) / static_cast<double>(per_tile)));
    };
    for (const Cloud& part : sink.parts) {
      for (const auto& p : part) {  // one tile per part, inside the announced bounds
        EXPECT_EQ(tileOf(p.x()), tileOf(part[0].x()));
        EXPECT_EQ(tileOf(p.y()), tileOf(part[0].y()));
        EXPECT_TRUE(sink.bounds.contains(p));
      }
      got.insert(got.end(), part.begin(), part.end());
    }
    expectBitEqual(sortedBits(got), sortedBits(want));
    for (const auto& kf : kfs) EXPECT_TRUE(clouds.get(kf.cloud).empty()) << "cloud not released";
  }
}

TEST(MapTiles, OneTileIsVoxelFilterInItsOrderAndDiskGivesTheSame) {
  Drive d = randomDrive(9, 12);
  for (auto& T : d.poses)
    T.translation() += Eigen::Vector3d(500.0, 500.0, 0.0);  // all in tile (0, 0)
  const Cloud want = voxelFilter(joined(d), 0.2);
  CloudStore memory;
  CollectedMap one;
  buildMapByTiles(memory, store(d, memory), 0.2, 1e5, one);
  expectBitEqual(one.map, want);

  const auto dir = slamroute::test::testTmp() / "map_tiles";
  std::filesystem::create_directories(dir);
  CloudStore disk(dir);
  CloudStore memory2;
  CollectedMap from_disk, from_memory;
  buildMapByTiles(disk, store(d, disk), 0.2, 10.0, from_disk);
  buildMapByTiles(memory2, store(d, memory2), 0.2, 10.0, from_memory);
  expectBitEqual(from_disk.map, from_memory.map);
}

TEST(MapTiles, NoVoxelKeepsEveryPointInKeyframeOrderAndBadTilesThrow) {
  const Drive d = randomDrive(3, 4);
  CloudStore clouds;
  const auto kfs = store(d, clouds);
  CollectedMap all;
  EXPECT_EQ(buildMapByTiles(clouds, kfs, 0.0, 50.0, all), joined(d).size());
  expectBitEqual(all.map, joined(d));

  CloudStore again;
  CollectedMap none;
  EXPECT_THROW(buildMapByTiles(again, store(d, again), 0.2, 0.0, none), std::invalid_argument);
  CloudStore empty;
  PartsSink nothing;
  EXPECT_EQ(buildMapByTiles(empty, {}, 0.2, 50.0, nothing), 0u);
  EXPECT_EQ(nothing.begins, 1);
  EXPECT_TRUE(nothing.bounds.isEmpty());
  EXPECT_TRUE(nothing.parts.empty());
}

}  // namespace
}  // namespace slamroute::evaluate
