// The k-d tree against a brute-force search, on point layouts that exercise its splits: spread
// out, all on one plane (the cut often lands on points), on a grid (many equal distances), a
// single repeated point (no side to cut) and clusters far apart. The answer is exact, ties
// included: at equal distances the lower index comes first.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <utility>

#include "slamroute/evaluate/KdTree.hpp"

namespace slamroute::evaluate {
namespace {

using Points = std::vector<Eigen::Vector3f>;

Points layout(const std::string& name) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-20.0f, 20.0f);
  Points pts;
  if (name == "spread")
    for (int i = 0; i < 2000; ++i) pts.emplace_back(u(rng), u(rng), 0.1f * u(rng));
  if (name == "plane")
    for (int i = 0; i < 2000; ++i) pts.emplace_back(u(rng), u(rng), 0.0f);
  if (name == "grid")
    for (int x = 0; x < 15; ++x)
      for (int y = 0; y < 15; ++y)
        for (int z = 0; z < 4; ++z)
          pts.emplace_back(0.5f * static_cast<float>(x), 0.5f * static_cast<float>(y),
                           0.5f * static_cast<float>(z));
  if (name == "one_point") pts.assign(500, Eigen::Vector3f(1.0f, 2.0f, 3.0f));
  if (name == "clusters")
    for (int i = 0; i < 900; ++i)
      pts.emplace_back(1000.0f * static_cast<float>(i % 3) + 0.01f * u(rng), 0.01f * u(rng),
                       0.01f * u(rng));
  return pts;
}

/// The k nearest within the bound (squared distance and index), by sorting all of them: at
/// equal distances the lower index first.
std::vector<std::pair<float, int>> bruteForce(const Points& pts, const Eigen::Vector3f& q, int k,
                                              float bound) {
  std::vector<std::pair<float, int>> all;
  for (std::size_t i = 0; i < pts.size(); ++i)
    if (float d2 = treeSqDist(pts[i], q); d2 <= bound) all.emplace_back(d2, static_cast<int>(i));
  std::sort(all.begin(), all.end());
  all.resize(std::min(all.size(), static_cast<std::size_t>(k)));
  return all;
}

std::vector<std::pair<float, int>> zipped(const std::vector<float>& d2,
                                          const std::vector<int>& idx) {
  std::vector<std::pair<float, int>> out;
  EXPECT_EQ(d2.size(), idx.size());
  for (std::size_t i = 0; i < idx.size(); ++i) out.emplace_back(d2.at(i), idx[i]);
  return out;
}

class KdTreeLayout : public ::testing::TestWithParam<std::string> {};

TEST_P(KdTreeLayout, NearestNeighboursEqualABruteForceSearch) {
  const Points pts = layout(GetParam());
  KdTree tree;
  tree.build(pts);
  ASSERT_EQ(tree.size(), pts.size());
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-25.0f, 25.0f);
  std::vector<int> idx;
  std::vector<float> d2;
  for (int q = 0; q < 200; ++q) {
    // Queries on the points themselves as well as anywhere (also outside the points' box).
    const Eigen::Vector3f query = q % 2 ? pts[static_cast<std::size_t>(q) % pts.size()]
                                        : Eigen::Vector3f(u(rng), u(rng), u(rng));
    for (const int k : {1, 5, 12}) {
      const auto want = bruteForce(pts, query, k, 1e30f);
      ASSERT_EQ(tree.knn(query, k, idx, d2), static_cast<int>(want.size()));
      EXPECT_EQ(zipped(d2, idx), want);
      // Within a bound: the same neighbours as far as they lie within it, a point at exactly
      // the bound kept.
      const float bound = want[want.size() / 2].first;
      const auto within = bruteForce(pts, query, k, bound);
      ASSERT_EQ(tree.knnWithin(query, k, bound, idx, d2), static_cast<int>(within.size()));
      EXPECT_EQ(zipped(d2, idx), within);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Layouts, KdTreeLayout,
                         ::testing::Values("spread", "plane", "grid", "one_point", "clusters"));

TEST(KdTree, AnEmptyTreeFindsNothingAndAskingForMoreThanThereAreGivesAll) {
  KdTree empty;
  empty.build({});
  std::vector<int> idx;
  std::vector<float> d2;
  EXPECT_EQ(empty.knn(Eigen::Vector3f::Zero(), 5, idx, d2), 0);
  const Points pts = layout("spread");
  KdTree tree;
  tree.build(pts);
  EXPECT_EQ(tree.knn(Eigen::Vector3f::Zero(), 5000, idx, d2), 2000);
  std::sort(idx.begin(), idx.end());
  EXPECT_EQ(std::unique(idx.begin(), idx.end()), idx.end());  // every point once
  EXPECT_TRUE(std::is_sorted(d2.begin(), d2.end()));
  tree.build({});  // rebuilt empty: nothing left of the old points
  EXPECT_EQ(tree.knn(Eigen::Vector3f::Zero(), 5, idx, d2), 0);
}

}  // namespace
}  // namespace slamroute::evaluate
