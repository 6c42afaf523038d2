// Hungarian assignment: known answers, and the exact minimum of brute force on random matrices.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <stdexcept>
#include <tuple>

#include "slamroute/core/Hungarian.hpp"

namespace slamroute {
namespace {

using Matrix = std::vector<std::vector<double>>;

/// Minimum total cost over every injective map of the smaller side into the larger.
double bruteForceMinimum(const Matrix& c) {
  const std::size_t rows = c.size(), cols = c.front().size();
  const std::size_t big = std::max(rows, cols), small = std::min(rows, cols);
  std::vector<std::size_t> perm(big);
  std::iota(perm.begin(), perm.end(), 0);
  double best = std::numeric_limits<double>::infinity();
  do {  // the first `small` entries of each permutation name the partners of the small side
    double sum = 0.0;
    for (std::size_t s = 0; s < small; ++s) sum += rows <= cols ? c[s][perm[s]] : c[perm[s]][s];
    best = std::min(best, sum);
  } while (std::next_permutation(perm.begin(), perm.end()));
  return best;
}

void expectValid(const Matrix& c, const Assignment& a) {
  ASSERT_EQ(a.columnOfRow.size(), c.size());
  std::vector<int> used(c.front().size(), 0);
  double sum = 0.0;
  int assigned = 0;
  for (std::size_t r = 0; r < c.size(); ++r) {
    if (a.columnOfRow[r] < 0) continue;
    ++used.at(a.columnOfRow[r]);
    sum += c[r][a.columnOfRow[r]];
    ++assigned;
  }
  for (int u : used) EXPECT_LE(u, 1);
  EXPECT_EQ(assigned, static_cast<int>(std::min(c.size(), c.front().size())));
  EXPECT_NEAR(sum, a.totalCost, 1e-9);
}

TEST(Hungarian, KnownThreeByThree) {
  // By hand: (0->1, 1->0, 2->2) = 1 + 2 + 2 = 5; the other permutations cost 7, 9, 11, 11, 11.
  const Matrix c = {{4, 1, 3}, {2, 5, 5}, {3, 2, 2}};
  const Assignment a = hungarianAssignment(c);
  EXPECT_EQ(a.columnOfRow, (std::vector<int>{1, 0, 2}));
  EXPECT_DOUBLE_EQ(a.totalCost, 5.0);
}

TEST(Hungarian, MoreRowsThanColumnsLeavesTheCostliestRowsOut) {
  const Matrix c = {{10, 10}, {1, 9}, {9, 1}};
  const Assignment a = hungarianAssignment(c);
  EXPECT_EQ(a.columnOfRow, (std::vector<int>{-1, 0, 1}));
  EXPECT_DOUBLE_EQ(a.totalCost, 2.0);
}

TEST(Hungarian, NegativeCostsAndEmptyAndBadInput) {
  EXPECT_DOUBLE_EQ(hungarianAssignment({{-5, 0}, {0, -5}}).totalCost, -10.0);
  EXPECT_TRUE(hungarianAssignment({}).columnOfRow.empty());
  EXPECT_THROW(hungarianAssignment({{1, 2}, {3}}), std::invalid_argument);
  EXPECT_THROW(hungarianAssignment({{1, std::numeric_limits<double>::infinity()}}),
               std::invalid_argument);
}

class HungarianBruteForce : public ::testing::TestWithParam<std::tuple<int, int>> {};

TEST_P(HungarianBruteForce, MatchesTheMinimumOverAllAssignments) {
  const auto [rows, cols] = GetParam();
  std::mt19937 rng(rows * 31 + cols);
  std::uniform_int_distribution<int> value(0, 20);  // small integers: many ties
  for (int trial = 0; trial < 30; ++trial) {
    Matrix c(rows, std::vector<double>(cols));
    for (auto& row : c)
      for (double& x : row) x = value(rng) + (trial % 3 == 0 ? 0.0 : 0.37 * value(rng));
    const Assignment a = hungarianAssignment(c);
    expectValid(c, a);
    EXPECT_NEAR(a.totalCost, bruteForceMinimum(c), 1e-9) << "trial " << trial;
  }
}

INSTANTIATE_TEST_SUITE_P(Sizes, HungarianBruteForce,
                         ::testing::Values(std::tuple{1, 1}, std::tuple{2, 2}, std::tuple{3, 3},
                                           std::tuple{5, 5}, std::tuple{7, 7}, std::tuple{2, 5},
                                           std::tuple{3, 7}, std::tuple{6, 2}, std::tuple{7, 4},
                                           std::tuple{1, 6}, std::tuple{6, 1}));

}  // namespace
}  // namespace slamroute
