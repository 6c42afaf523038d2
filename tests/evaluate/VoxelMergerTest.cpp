// VoxelMerger (the SLAM map built keyframe by keyframe) must give exactly what voxelFilter gives
// for all clouds joined: same voxels, same order, same float sums.
#include <gtest/gtest.h>

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
