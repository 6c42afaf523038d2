// bench/sideways_steps.py on hand-made ground truths: a drive along its heading has no sideways
// step; one that SUMO moves 1.5 m to the left in three 0.1 s steps has exactly those three, 1.5 m
// across in all, the largest at its time and on its SUMO edge. A missing ground truth is one line
// naming the file.
#include <gtest/gtest.h>

#include <fstream>

#include "CliTestUtil.hpp"

namespace {
namespace fs = std::filesystem;

slamroute::test::CliResult runScript(const std::string& args) {
  return slamroute::test::runCommand("/usr/bin/python3 " + std::string(SLAMROUTE_SOURCE_DIR) +
                                     "/bench/sideways_steps.py " + args);
}

/// Along +x at 5 m/s for 10 s at 10 Hz, heading +x; with `jump`, 0.5 m to the left in each of
/// the steps ending at 5.1, 5.2 and 5.3 s; pose_edges.csv puts the poses from 5 s on edge "e2".
void writeDrive(const fs::path& dir, bool jump) {
  fs::create_directories(dir);
  std::ofstream gt(dir / "groundtruth.tum"), edges(dir / "pose_edges.csv");
  gt << "# t x y z qx qy qz qw\n";
  edges << "t,sumo_edge,lane_pos_m\n";
  for (int i = 0; i <= 100; ++i) {
    const double t = 0.1 * i;
    const double y = jump ? 0.5 * std::min(3, std::max(0, i - 50)) : 0.0;
    gt << t << ' ' << 5.0 * t << ' ' << y << " 1.8 0 0 0 1\n";
    edges << t << ',' << (i < 50 ? "e1" : "e2") << ',' << 0.5 * t << '\n';
  }
}

TEST(SidewaysStepsScript, CountsTheStepsThatMoveAcrossTheHeading) {
  const fs::path root = slamroute::test::cliTempDir("sideways_steps");
  writeDrive(root / "straight", false);
  writeDrive(root / "jump", true);
  const auto r = runScript((root / "straight").string() + " " + (root / "jump").string());
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find((root / "straight").string() +
                       ": 0 steps over 3.0 m/s across the heading, 0.00 m across in them"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find((root / "jump").string() +
                       ": 3 steps over 3.0 m/s across the heading, 1.50 m across in them; "
                       "largest 0.50 m in 0.1 s at t 5.0 s on e2"),
            std::string::npos)
      << r.out;
  // 5 m/s across is below a threshold of 6 m/s.
  const auto slow = runScript("--speed 6 " + (root / "jump").string());
  EXPECT_NE(slow.out.find(": 0 steps over 6.0 m/s"), std::string::npos) << slow.out;
}

TEST(SidewaysStepsScript, AMissingGroundTruthIsOneLineNamingTheFile) {
  const fs::path root = slamroute::test::cliTempDir("sideways_steps_bad");
  fs::create_directories(root / "empty");
  const auto r = runScript((root / "empty").string());
  EXPECT_NE(r.code, 0);
  EXPECT_EQ(r.out,
            "sideways_steps.py: " + (root / "empty/groundtruth.tum").string() + ": no such file\n");
  const auto bad = runScript("--speed -1 " + (root / "empty").string());
  EXPECT_NE(bad.code, 0);
  EXPECT_EQ(bad.out, "sideways_steps.py: --speed must be a positive number of m/s\n");
}

}  // namespace
