#include <gtest/gtest.h>

#include <cmath>

#include "Report.hpp"

namespace slamroute::cli {
namespace {

TEST(Report, SpearmanKnownAnswers) {
  EXPECT_NEAR(spearman({1, 2, 3, 4}, {10, 20, 30, 40}), 1.0, 1e-12);
  EXPECT_NEAR(spearman({1, 2, 3, 4}, {9, 7, 3, 1}), -1.0, 1e-12);
  // Monotone but non-linear is still rank-perfect.
  EXPECT_NEAR(spearman({1, 2, 3, 4, 5}, {1, 4, 9, 16, 25}), 1.0, 1e-12);
  // With ties: ranks x = {1,2.5,2.5,4}, y = {1,3,2,4}; Pearson of ranks = 4.5 / sqrt(4.5 * 5).
  EXPECT_NEAR(spearman({1, 2, 2, 3}, {1, 3, 2, 4}), 0.9486832980505138, 1e-12);
  EXPECT_TRUE(std::isnan(spearman({1, 2}, {1, 2})));
  EXPECT_TRUE(std::isnan(spearman({1, 1, 1}, {1, 2, 3})));
}

}  // namespace
}  // namespace slamroute::cli
