// VoxelMerger (the SLAM map built keyframe by keyframe) must give exactly what voxelFilter gives
// for all clouds joined: same voxels, same order, same float sums.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <random>

#include "slamroute/evaluate/Features.hpp"

namespace slamroute::evaluate {
namespace {

Cloud randomCloud(std::mt19937& rng, int n, float spread) {
  std::uniform_real_distribution<float> u(-spread, spread);
  Cloud c;
  for (int i = 0; i < n; ++i) c.emplace_back(u(rng), u(rng), 0.1f * u(rng));
  return c;
}

void expectBitEqual(const Cloud& a, const Cloud& b) {
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(Eigen::Vector3f)), 0);
}

/// voxelFilter written out the plain way: the (voxel, index) pairs sorted, each voxel's points
/// summed in input order.
Cloud voxelFilterBySort(const Cloud& in, double voxel_m) {
  const auto inv = static_cast<float>(1.0 / voxel_m);
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keys;
  for (std::size_t i = 0; i < in.size(); ++i)
    keys.emplace_back(voxelKey(in[i], inv), static_cast<std::uint32_t>(i));
  std::sort(keys.begin(), keys.end());
  Cloud out;
  for (std::size_t a = 0; a < keys.size();) {
    Eigen::Vector3f sum = Eigen::Vector3f::Zero();
    std::size_t b = a;
    while (b < keys.size() && keys[b].first == keys[a].first) sum += in[keys[b++].second];
    out.push_back(sum / static_cast<float>(b - a));
    a = b;
  }
  return out;
}

TEST(VoxelFilter, GivesBitForBitTheSortedPairsResult) {
  std::mt19937 rng(11);
  // A city-sized spread (keys differ in their high bits) and a small one (most digits shared),
  // including negative coordinates.
  for (const float spread : {0.5f, 40.0f, 3000.0f}) {
    const Cloud c = randomCloud(rng, 20000, spread);
    expectBitEqual(voxelFilter(c, 0.2), voxelFilterBySort(c, 0.2));
  }
}

TEST(VoxelMerger, GivesBitForBitWhatVoxelFilterGivesForTheJoinedClouds) {
  std::mt19937 rng(7);
  std::vector<Cloud> clouds;
  Cloud joined;
  for (int k = 0; k < 40; ++k) {  // overlapping clouds: most voxels get points from several
    clouds.push_back(randomCloud(rng, 300 + 50 * (k % 5), 4.0f));
    joined.insert(joined.end(), clouds.back().begin(), clouds.back().end());
  }
  const Cloud want = voxelFilter(joined, 0.5);
  ASSERT_LT(want.size(), joined.size() / 2);  // many voxels hold several points
  // Chunks smaller than one cloud, a few clouds, and all at once.
  for (std::size_t chunk : {100u, 1000u, 5000u, 1000000u}) {
    VoxelMerger m(0.5, chunk);
    for (const auto& c : clouds) m.add(c);
    expectBitEqual(m.finish(), want);
  }
}

TEST(VoxelMerger, NoVoxelKeepsEveryPointAndNoPointsGiveNoMap) {
  std::mt19937 rng(3);
  const Cloud a = randomCloud(rng, 10, 1.0f), b = randomCloud(rng, 5, 1.0f);
  VoxelMerger keep(0.0, 4);
  keep.add(a);
  keep.add(b);
  Cloud joined = a;
  joined.insert(joined.end(), b.begin(), b.end());
  expectBitEqual(keep.finish(), joined);
  VoxelMerger none(0.2);
  none.add({});
  EXPECT_TRUE(none.finish().empty());
}

}  // namespace
}  // namespace slamroute::evaluate
