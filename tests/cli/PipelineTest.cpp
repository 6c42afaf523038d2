// Pieces of `run` / `experiment` (cli/Pipeline.hpp) that need no child process.
#include "TestTmp.hpp"
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "Pipeline.hpp"

namespace slamroute::cli {
namespace {
namespace fs = std::filesystem;

TEST(Pipeline, ResumeSkipsOnlyStepsWhoseOutputExists) {
  const fs::path dir = slamroute::test::testTmp() / "pipeline_resume";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "done.json") << "{}\n";
  std::vector<Step> steps(3);
  steps[0].label = "finished";
  steps[0].output = dir / "done.json";
  steps[1].label = "not yet";
  steps[1].output = dir / "missing.json";
  steps[2].label = "no output";
  const std::vector<Step> left = stepsNotDone(steps);
  ASSERT_EQ(left.size(), 2u);
  EXPECT_EQ(left[0].label, "not yet");
  EXPECT_EQ(left[1].label, "no output");
  fs::remove_all(dir);
}

}  // namespace
}  // namespace slamroute::cli
