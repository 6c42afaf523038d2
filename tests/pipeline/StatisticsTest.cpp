// The statistics of study results (pipeline/Statistics.hpp) against values worked by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "slamroute/pipeline/Statistics.hpp"

namespace slamroute::pipeline {
namespace {

TEST(Statistics, RanksShareTheMeanRankOfTies) {
  EXPECT_EQ(ranks({30, 10, 20}), (std::vector<double>{3, 1, 2}));
  EXPECT_EQ(ranks({5, 1, 5, 5}), (std::vector<double>{3, 1, 3, 3}));  // 2, 3, 4 shared
}

TEST(Statistics, SpearmanOfKnownSamples) {
  EXPECT_NEAR(spearman({1, 2, 3, 4}, {10, 20, 30, 40}), 1.0, 1e-12);
  EXPECT_NEAR(spearman({1, 2, 3, 4}, {9, 7, 3, 1}), -1.0, 1e-12);
  // Ranks (1,2,3,4,5) vs (2,1,4,3,5): sum d^2 = 4, rho = 1 - 6*4/(5*24) = 0.8.
  EXPECT_NEAR(spearman({1, 2, 3, 4, 5}, {2, 1, 4, 3, 5}), 0.8, 1e-12);
  EXPECT_TRUE(std::isnan(spearman({1, 2}, {1, 2})));
  EXPECT_TRUE(std::isnan(spearman({1, 2, 3}, {4, 4, 4})));
}

TEST(Statistics, MeanAndSampleStandardDeviation) {
  // 2, 4, 4, 4, 5, 5, 7, 9: mean 5, squared deviations sum 32, sample sd sqrt(32 / 7).
  const MeanSd s = meanSd({2, 4, 4, 4, 5, 5, 7, 9});
  EXPECT_EQ(s.n, 8u);
  EXPECT_DOUBLE_EQ(s.mean, 5.0);
  EXPECT_NEAR(s.sd, std::sqrt(32.0 / 7.0), 1e-12);
  EXPECT_EQ(meanSd({3.5}).sd, 0.0);
  EXPECT_EQ(meanSd({}).n, 0u);
  EXPECT_EQ(formatMeanSd(meanSd({1, 3}), 2), "2.00 ± 1.41");
  EXPECT_EQ(formatMeanSd(meanSd({}), 2), "–");
}

}  // namespace
}  // namespace slamroute::pipeline
