// The local map's voxel cells: adding clouds and taking some out again leaves the centroids of
// the clouds that stay, as voxelFilter gives them.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "slam/VoxelCells.hpp"

namespace slamroute::evaluate::slam {
namespace {

Cloud randomCloud(int n, unsigned seed, float offset) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-3.0F, 3.0F);
  Cloud c;
  for (int i = 0; i < n; ++i) c.emplace_back(u(rng) + offset, u(rng), u(rng) * 0.2F);
  return c;
}

Cloud sorted(Cloud c) {
  std::sort(c.begin(), c.end(), [](const auto& a, const auto& b) {
    return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
  });
  return c;
}

void expectSameClouds(const Cloud& got, const Cloud& want) {
  ASSERT_EQ(got.size(), want.size());
  const Cloud g = sorted(got), w = sorted(want);
  for (std::size_t i = 0; i < g.size(); ++i) EXPECT_LT((g[i] - w[i]).norm(), 1e-5F) << i;
}

TEST(VoxelCells, CentroidsAreTheVoxelFilterOfWhatWasAdded) {
  VoxelCells cells(0.4);
  const Cloud a = randomCloud(2000, 1, 0.0F), b = randomCloud(2000, 2, 2.0F);
  cells.add(a);
  cells.add(b);
  Cloud ab = a;
  ab.insert(ab.end(), b.begin(), b.end());
  expectSameClouds(cells.centroids(), voxelFilter(ab, 0.4));
}

TEST(VoxelCells, TakingACloudOutLeavesTheOthersCentroids) {
  VoxelCells cells(0.4);
  const Cloud a = randomCloud(2000, 1, 0.0F), b = randomCloud(2000, 2, 2.0F),
              c = randomCloud(500, 3, 4.0F);
  cells.add(a);
  cells.add(b);
  cells.add(c);
  cells.remove(a);
  cells.remove(c);
  expectSameClouds(cells.centroids(), voxelFilter(b, 0.4));
  cells.remove(b);
  EXPECT_EQ(cells.size(), 0U);
}

TEST(VoxelCells, RejectsAZeroVoxelAndPointsNeverAdded) {
  EXPECT_THROW(VoxelCells(0.0), std::invalid_argument);
  VoxelCells cells(0.5);
  cells.add({Eigen::Vector3f(0.1F, 0.1F, 0.1F)});
  EXPECT_THROW(cells.remove({Eigen::Vector3f(10.0F, 0.0F, 0.0F)}), std::logic_error);
}

}  // namespace
}  // namespace slamroute::evaluate::slam
