// KeptNeighbours must answer exactly as the tree search does, whether it searched or not, ties
// included.
#include <gtest/gtest.h>

#include <random>

#include "KeptNeighbours.hpp"

namespace slamroute::evaluate {
namespace {

TEST(KeptNeighbours, AnswersAsTheTreeSearchAlongAWalkOfSmallAndLargeSteps) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(-10.0f, 10.0f);
  Cloud cloud;
  for (int i = 0; i < 5000; ++i) cloud.emplace_back(u(rng), u(rng), 0.2f * u(rng));
  KdTree tree;
  tree.build(cloud);
  std::normal_distribution<float> small(0.0f, 0.003f), large(0.0f, 0.3f);
  const float max_sq = 0.8f * 0.8f;
  int reused = 0, searched = 0;
  for (int start = 0; start < 50; ++start) {
    KeptNeighbours<5> kept;
    Eigen::Vector3f q(u(rng), u(rng), 0.2f * u(rng));
    for (int step = 0; step < 40; ++step) {
      auto& d = step % 7 == 6 ? large : small;  // mostly settling, now and then a jump
      q += Eigen::Vector3f(d(rng), d(rng), d(rng));
      std::vector<int> idx, want_idx;
      std::vector<float> d2, want_d2;
      const int n = kept.find(tree, cloud, q, max_sq, idx, d2);
      const int want = tree.knnWithin(q, 5, max_sq, want_idx, want_d2);
      ASSERT_EQ(n, want);
      if (want == 5) {
        EXPECT_EQ(idx, want_idx);
        EXPECT_EQ(d2, want_d2);
      }
      (kept.reused() ? reused : searched) += 1;
    }
  }
  // Both ways were taken, most steps without a search.
  EXPECT_GT(searched, 50);
  EXPECT_GT(reused, searched);
}

TEST(KeptNeighbours, NothingWithinTheBoundIsFoundAndNotKept) {
  const Cloud cloud{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {4, 0, 0}, {5, 0, 0}};
  KdTree tree;
  tree.build(cloud);
  KeptNeighbours<5> kept;
  std::vector<int> idx;
  std::vector<float> d2;
  EXPECT_EQ(kept.find(tree, cloud, {2.5f, 0, 0}, 1.0f, idx, d2), 2);  // only 2 and 3 within 1 m
  EXPECT_EQ(kept.find(tree, cloud, {2.5f, 0, 0}, 100.0f, idx, d2), 5);
  EXPECT_FALSE(kept.reused());
  EXPECT_EQ(kept.find(tree, cloud, {2.5f, 0, 0.001f}, 100.0f, idx, d2), 5);
  EXPECT_FALSE(kept.reused());  // 0 and 5 are at the same 2.5 m: the fifth is not certain
}

TEST(KeptNeighbours, PointsThatBecomeTiedComeInTheTreesOrder) {
  Cloud grid;  // integer points, x outermost: (-1, 0, 0) has a lower index than (1, 0, 0)
  for (int x = -3; x <= 3; ++x)
    for (int y = -3; y <= 3; ++y)
      for (int z = -3; z <= 3; ++z)
        grid.emplace_back(static_cast<float>(x), static_cast<float>(y), static_cast<float>(z));
  KdTree tree;
  tree.build(grid);
  KeptNeighbours<5> kept;
  std::vector<int> idx, want_idx;
  std::vector<float> d2, want_d2;
  // Off the symmetry plane x = 0, (1, 0, 0) is the 4th and (-1, 0, 0) the 5th; on it they tie.
  ASSERT_EQ(kept.find(tree, grid, {0.001f, 0.2f, 0.1f}, 100.0f, idx, d2), 5);
  ASSERT_EQ(kept.find(tree, grid, {0.0f, 0.2f, 0.1f}, 100.0f, idx, d2), 5);
  EXPECT_TRUE(kept.reused());
  tree.knnWithin({0.0f, 0.2f, 0.1f}, 5, 100.0f, want_idx, want_d2);
  EXPECT_EQ(d2[3], d2[4]);
  EXPECT_EQ(idx, want_idx);
}

}  // namespace
}  // namespace slamroute::evaluate
