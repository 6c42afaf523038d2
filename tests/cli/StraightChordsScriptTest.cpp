// bench/straight_chords.py on hand-made trajectories: a drive east at 10 m/s whose estimate is
// 0.1 % short is 0.99900 of the truth east-west, each 2 s window (20 m) 20 mm short; an exact
// copy is 1.00000 with windows of 0 mm; a drive north is counted north-south.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "CliTestUtil.hpp"

namespace {
namespace fs = std::filesystem;

slamroute::test::CliResult runScript(const fs::path& drive, const fs::path& eval) {
  return slamroute::test::runCommand("/usr/bin/python3 " + std::string(SLAMROUTE_SOURCE_DIR) +
                                     "/bench/straight_chords.py " + drive.string() + " " +
                                     eval.string());
}

/// 60 s straight at 10 m/s, 10 poses a second, heading `yaw` (0: east, pi/2: north), the
/// distance driven multiplied by `scale`.
void writeStraight(const fs::path& file, double yaw, double scale) {
  std::ofstream out(file);
  out << "# t x y z qx qy qz qw\n";
  for (int k = 0; k <= 600; ++k) {
    const double s = scale * k;  // 1 m per pose
    out << 0.1 * k << ' ' << 100 + s * std::cos(yaw) << ' ' << 200 + s * std::sin(yaw)
        << " 1.8 0 0 " << std::sin(yaw / 2) << ' ' << std::cos(yaw / 2) << '\n';
  }
}

TEST(StraightChordsScript, AnEstimateShortByATenthOfAPercentIsShortOnEveryWindow) {
  const fs::path root = slamroute::test::cliTempDir("straight_chords");
  for (const char* d : {"east", "east_same", "east_short", "north", "north_short"})
    fs::create_directories(root / d);
  writeStraight(root / "east/groundtruth.tum", 0.0, 1.0);
  writeStraight(root / "east_same/estimate.tum", 0.0, 1.0);
  writeStraight(root / "east_short/estimate.tum", 0.0, 0.999);
  writeStraight(root / "north/groundtruth.tum", M_PI / 2, 1.0);
  writeStraight(root / "north_short/estimate.tum", M_PI / 2, 0.999);

  const auto same = runScript(root / "east", root / "east_same");
  ASSERT_EQ(same.code, 0) << same.out;
  EXPECT_NE(same.out.find("EW: estimate / truth 1.00000 over"), std::string::npos) << same.out;
  EXPECT_NE(same.out.find("median window +0.0 mm"), std::string::npos) << same.out;

  const auto short_east = runScript(root / "east", root / "east_short");
  ASSERT_EQ(short_east.code, 0) << short_east.out;
  EXPECT_NE(short_east.out.find("EW: estimate / truth 0.99900 over"), std::string::npos)
      << short_east.out;
  EXPECT_NE(short_east.out.find("median window -20.0 mm"), std::string::npos) << short_east.out;
  EXPECT_EQ(short_east.out.find("NS:"), std::string::npos) << short_east.out;

  const auto short_north = runScript(root / "north", root / "north_short");
  ASSERT_EQ(short_north.code, 0) << short_north.out;
  EXPECT_NE(short_north.out.find("NS: estimate / truth 0.99900 over"), std::string::npos)
      << short_north.out;
}

}  // namespace
