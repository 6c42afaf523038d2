// Pieces of `run` / `experiment` (cli/Pipeline.hpp) that need no child process.
#include <gtest/gtest.h>
#include "TestTmp.hpp"

#include "Pipeline.hpp"

namespace slamroute::cli {
namespace {
namespace fs = std::filesystem;

TEST(Pipeline, SlamMemoryEstimateLiesAboveTheMeasuredPeaks) {
  // Keyframe clouds on disk (the default), the map merged tile by tile: default city, qlearning:
  // peak 330,444 kB; Ingolstadt, postman: 698,780 kB.
  EXPECT_GT(slamMemoryGb(14.9), 0.338);
  EXPECT_GT(slamMemoryGb(74.5), 0.716);
  EXPECT_LT(slamMemoryGb(74.5), 1.1);  // not so far above that it wastes the machine
  // In memory: 601,096 kB and 2,496,008 kB.
  EXPECT_GT(slamMemoryGb(14.9, false), 0.616);
  EXPECT_GT(slamMemoryGb(74.5, false), 2.56);
  EXPECT_LT(slamMemoryGb(74.5, false), 3.5);
  EXPECT_NEAR(slamMemoryGb(0.0), 0.3, 1e-12);
}

TEST(Pipeline, SlamJobsStartOnlyAsManyRunsAsTheMemoryHolds) {
  // Three runs of 8, 5 and 4 GB: all fit in 20 GB; in 16 GB only the two largest (13 GB) do; in
  // 12 GB one at a time; never fewer than one, even when the largest alone does not fit.
  EXPECT_EQ(slamJobsForMemory({5.0, 8.0, 4.0}, 20.0, 3), 3);
  EXPECT_EQ(slamJobsForMemory({5.0, 8.0, 4.0}, 16.0, 3), 2);
  EXPECT_EQ(slamJobsForMemory({5.0, 8.0, 4.0}, 12.0, 3), 1);
  EXPECT_EQ(slamJobsForMemory({5.0, 8.0, 4.0}, 6.0, 3), 1);
  // max_jobs and the number of runs bound it; an unknown budget (0) limits nothing else.
  EXPECT_EQ(slamJobsForMemory({1.0, 1.0, 1.0}, 100.0, 2), 2);
  EXPECT_EQ(slamJobsForMemory({1.0}, 100.0, 4), 1);
  EXPECT_EQ(slamJobsForMemory({5.0, 8.0, 4.0}, 0.0, 3), 3);
}

TEST(Pipeline, AvailableMemoryIsReadFromTheSystem) {
  const double gb = availableMemoryGb();
  EXPECT_GT(gb, 0.1);     // this machine has memory available
  EXPECT_LT(gb, 4096.0);  // in GB, not kB
}

}  // namespace
}  // namespace slamroute::cli
