// bench/false_closures.py on a hand-made experiment folder: a closure whose measured relative
// pose is 1.5 m off the ground truth's is false at 1 m and not at 2 m; one without the measured
// pose is counted apart.
#include <gtest/gtest.h>

#include <fstream>

#include "CliTestUtil.hpp"

namespace {
namespace fs = std::filesystem;

slamroute::test::CliResult runScript(const std::string& args) {
  return slamroute::test::runCommand("python3 " + std::string(SLAMROUTE_SOURCE_DIR) +
                                     "/bench/false_closures.py " + args);
}

TEST(FalseClosuresScript, CountsClosuresFartherOffThanTheLimit) {
  const fs::path root = slamroute::test::cliTempDir("false_closures") / "exp";
  fs::create_directories(root / "drives/d1");
  fs::create_directories(root / "eval/d1");
  // (0,0) heading east; (10,0) heading north; (0.5,0) heading west
  std::ofstream(root / "drives/d1/groundtruth.tum")
      << "# t x y z qx qy qz qw\n0 0 0 0 0 0 0 1\n10 10 0 0 0 0 0.7071067811865476 "
         "0.7071067811865476\n"
      << "20 0.5 0 0 0 0 1 0\n";
  // true: 0.2 m and 1 deg off; false: in the frame of the pose at t=10 the truth is (0, 9.5)
  std::ofstream(root / "eval/d1/metrics.json") << R"({"loops": [
    {"t_old": 0, "t_new": 20, "t_old_new": [0.5, 0.2, 0], "yaw_old_new_deg": 179},
    {"t_old": 10, "t_new": 20, "t_old_new": [0, 8.0, 0], "yaw_old_new_deg": 90},
    {"t_old": 0, "t_new": 10}]})";
  const auto r = runScript(root.string());
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("| exp/d1 | 3 | 1 | 1 | 1.50 | 1.00 |"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("| **all 1** | 3 | 1 | **1** | 1.50 | 1.00 |"), std::string::npos) << r.out;
  const auto lenient = runScript("--max-error-m 2 " + (root / "eval/d1").string() + ":" +
                                 (root / "drives/d1").string());
  ASSERT_EQ(lenient.code, 0) << lenient.out;
  EXPECT_NE(lenient.out.find("| d1 | 3 | 1 | 0 | 1.50 | 1.00 |"), std::string::npos) << lenient.out;
  EXPECT_NE(runScript((root / "nothing").string()).code, 0);
}

}  // namespace
