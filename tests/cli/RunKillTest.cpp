// `run` killed by SIGKILL (it cannot pass anything on): its running step learns it from the
// kernel (PR_SET_PDEATHSIG), stops and removes its staging folder instead of finishing as an
// orphan whose unstamped result a later `run --resume` would keep.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>

#include "CliTestUtil.hpp"

namespace slamroute {
namespace {
namespace fs = std::filesystem;

/// The pid in the name of survey's staging folder `.survey.tmp.PID` under `run`, or 0.
long stagingPid(const fs::path& run) {
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(run, ec)) {
    const std::string name = e.path().filename().string();
    if (name.rfind(".survey.tmp.", 0) == 0) return std::stol(name.substr(12));
  }
  return 0;
}

TEST(RunKill, AStepDiesWithItsKilledRunAndRemovesItsStagingFolder) {
  const auto dir = test::cliTempDir("run_kill");
  // Survey routes long enough that the survey is still running when the run is killed.
  std::ofstream(dir / "long.yaml") << "simulate:\n  survey:\n    route_length_m: 200000\n";
  const std::string grid = std::string(SLAMROUTE_SOURCE_DIR) + "/networks/test/grid3x3.net.xml";
  const pid_t run = ::fork();
  if (run == 0) {
    const std::string cfg = (dir / "long.yaml").string(), out = (dir / "run").string();
    ::execl(SLAMROUTE_BINARY, SLAMROUTE_BINARY, "--log-level", "quiet", "--config", cfg.c_str(),
            "run", "--net", grid.c_str(), "--out", out.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  long survey = 0;
  ASSERT_TRUE(test::waitFor([&] { return (survey = stagingPid(dir / "run")) != 0; }))
      << "the survey step never started";
  ::kill(run, SIGKILL);
  ::waitpid(run, nullptr, 0);
  EXPECT_TRUE(test::waitFor([&] { return test::processDead(survey); }))
      << "the survey step (pid " << survey << ") outlived its run";
  EXPECT_EQ(stagingPid(dir / "run"), 0) << "its staging folder is left";
  EXPECT_FALSE(fs::exists(dir / "run" / "survey"));
}

}  // namespace
}  // namespace slamroute
