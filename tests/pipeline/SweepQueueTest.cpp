// The sweep's scheduling state (pipeline/SweepQueue.hpp): order, memory, retries, skips.
#include <gtest/gtest.h>

#include "slamroute/pipeline/SweepQueue.hpp"

namespace slamroute::pipeline {
namespace {

TEST(SweepQueue, LongestReadyTaskFirstWithinTheMemory) {
  // 0 and 1 are ready; 2 needs 0, 3 needs 0 and 1.
  SweepQueue q({{{}, 1.0, 0.3}, {{}, 5.0, 0.3}, {{0}, 9.0, 4.0}, {{0, 1}, 2.0, 0.3}});
  EXPECT_EQ(q.next(10.0, true), 1u);
  q.started(1);
  EXPECT_EQ(q.next(10.0, false), 0u);
  q.started(0);
  EXPECT_EQ(q.next(10.0, false), std::nullopt);  // 2 and 3 wait for 0
  q.succeeded(0, 1.0);
  EXPECT_EQ(q.status(2).state, TaskState::Ready);
  EXPECT_EQ(q.status(3).state, TaskState::Waiting);  // still waits for 1
  // 2 needs 4 GB: not on a busy rank with 1 GB free, but on an idle one it runs anyway.
  EXPECT_EQ(q.next(1.0, false), std::nullopt);
  EXPECT_EQ(q.next(1.0, true), 2u);
  q.estimate(2, 9.0, 0.5);  // its route turned out short
  EXPECT_EQ(q.next(1.0, false), 2u);
}

TEST(SweepQueue, AFailedTaskRunsOnceMoreThenItsDependentsAreSkipped) {
  SweepQueue q({{{}, 1.0, 0.3}, {{0}, 1.0, 0.3}, {{1}, 1.0, 0.3}, {{}, 1.0, 0.3}});
  q.started(0);
  q.failed(0, "exit code 1");
  EXPECT_EQ(q.status(0).state, TaskState::Ready);  // retried
  q.started(0);
  q.requeue(0, "rank 1 died while running it");
  EXPECT_EQ(q.status(0).state, TaskState::Failed);
  EXPECT_EQ(q.status(0).attempts, 2);
  EXPECT_EQ(q.status(0).error, "rank 1 died while running it");
  EXPECT_EQ(q.status(1).state, TaskState::Skipped);
  EXPECT_EQ(q.status(2).state, TaskState::Skipped);  // through 1
  EXPECT_FALSE(q.finished());                        // 3 is independent and still ready
  q.started(3);
  q.succeeded(3, 2.0);
  EXPECT_TRUE(q.finished());
}

TEST(SweepQueue, DependenciesMustComeFirst) {
  EXPECT_THROW(SweepQueue({{{1}, 1.0, 0.3}, {{}, 1.0, 0.3}}), std::invalid_argument);
}

}  // namespace
}  // namespace slamroute::pipeline
