// bench/trajectory_error_split.py on hand-made trajectories: an exact copy of the truth has no
// error with or without a scale; a copy 0.1 % larger has a rigid ATE but none once the fit may
// scale it, and the fitted scale is 1 / 1.001; with --windows and --region, a copy with one
// stretch pushed aside puts most of the error in that stretch's window and box, and with
// --passes, where that stretch is a SUMO edge driven again, in the later passes. A missing or
// malformed trajectory ends it with one line naming the file.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>

#include "CliTestUtil.hpp"

namespace {
namespace fs = std::filesystem;

// Debian's interpreter: scripts/setup.sh installs numpy and scipy for it.
slamroute::test::CliResult runScript(const fs::path& drive, const fs::path& eval,
                                     const std::string& options = "") {
  return slamroute::test::runCommand("/usr/bin/python3 " + std::string(SLAMROUTE_SOURCE_DIR) +
                                     "/bench/trajectory_error_split.py " + options +
                                     drive.string() + " " + eval.string());
}

/// A 120 x 60 m loop driven anticlockwise, one pose per second (t = 0-35 s), heading along the
/// motion, the positions multiplied by `scale`; the poses from `bump_from` s on (12 of them:
/// the second long side, 18-29 s) moved 2 m aside.
void writeLoop(const fs::path& file, double scale, int bump_from = -1) {
  std::ofstream out(file);
  out << "# t x y z qx qy qz qw\n";
  const double corners[5][2] = {{0, 0}, {120, 0}, {120, 60}, {0, 60}, {0, 0}};
  int t = 0;
  for (int side = 0; side < 4; ++side) {
    const double dx = corners[side + 1][0] - corners[side][0];
    const double dy = corners[side + 1][1] - corners[side][1];
    const int steps = static_cast<int>(std::hypot(dx, dy) / 10);
    const double yaw = std::atan2(dy, dx);
    for (int k = 0; k < steps; ++k, ++t) {
      const double x = corners[side][0] + dx * k / steps, y = corners[side][1] + dy * k / steps;
      const double z = 0.5 * std::sin(0.3 * t);
      const double aside = bump_from >= 0 && t >= bump_from && t < bump_from + 12 ? 2.0 : 0.0;
      out << t << ' ' << scale * x << ' ' << scale * (y + aside) << ' ' << scale * z << " 0 0 "
          << std::sin(yaw / 2) << ' ' << std::cos(yaw / 2) << '\n';
    }
  }
}

/// A folder with drive/groundtruth.tum the loop and bumped/estimate.tum the loop with its second
/// long side (18-29 s) pushed 2 m aside.
fs::path bumpedLoop(const std::string& name) {
  const fs::path root = slamroute::test::cliTempDir(name);
  fs::create_directories(root / "drive");
  fs::create_directories(root / "bumped");
  writeLoop(root / "drive/groundtruth.tum", 1.0);
  writeLoop(root / "bumped/estimate.tum", 1.0, 18);
  return root;
}

TEST(TrajectoryErrorSplitScript, AFitWithAScaleTakesOutAUniformStretch) {
  const fs::path root = slamroute::test::cliTempDir("trajectory_error_split");
  fs::create_directories(root / "drive");
  fs::create_directories(root / "same");
  fs::create_directories(root / "larger");
  writeLoop(root / "drive/groundtruth.tum", 1.0);
  writeLoop(root / "same/estimate.tum", 1.0);
  writeLoop(root / "larger/estimate.tum", 1.001);

  const auto same = runScript(root / "drive", root / "same");
  ASSERT_EQ(same.code, 0) << same.out;
  EXPECT_NE(same.out.find("ATE RMSE 0.000 m;"), std::string::npos) << same.out;
  EXPECT_NE(same.out.find("with a scale: ATE RMSE 0.000 m, scale 1.00000"), std::string::npos)
      << same.out;

  const auto larger = runScript(root / "drive", root / "larger");
  ASSERT_EQ(larger.code, 0) << larger.out;
  EXPECT_EQ(larger.out.find("ATE RMSE 0.000 m;"), std::string::npos) << larger.out;
  EXPECT_NE(larger.out.find("with a scale: ATE RMSE 0.000 m, scale 0.99900"), std::string::npos)
      << larger.out;
}

TEST(TrajectoryErrorSplitScript, WindowsAndRegionsFindTheStretchThatCarriesTheError) {
  const fs::path root = bumpedLoop("trajectory_error_split_windows");

  const auto r = runScript(root / "drive", root / "bumped", "--windows 6 ");
  ASSERT_EQ(r.code, 0) << r.out;
  // Windows start at 0, 6, ..., 30 s; the bump fills those from 18 and 24 s.
  EXPECT_NE(r.out.find("windows of 6 s"), std::string::npos) << r.out;
  const auto largest = r.out.find("largest: the window from ");
  ASSERT_NE(largest, std::string::npos) << r.out;
  const double from = std::stod(r.out.substr(largest + 25));
  EXPECT_TRUE(from == 18.0 || from == 24.0) << r.out;
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 3 + 1 + 6 + 1) << r.out;

  // The box round the long side at y = 60 m holds the 12 pushed poses and the corner after them.
  const auto region = runScript(root / "drive", root / "bumped", "--region -1,121,55,65 ");
  ASSERT_EQ(region.code, 0) << region.out;
  const auto line = region.out.find("regions: 36.1 % of the poses, ");
  ASSERT_NE(line, std::string::npos) << region.out;
  EXPECT_GT(std::stod(region.out.substr(line + 30)), 50.0) << region.out;  // of the squared error

  const auto bad_region = runScript(root / "drive", root / "bumped", "--region 1,2 ");
  EXPECT_NE(bad_region.code, 0);
  EXPECT_EQ(bad_region.out, "trajectory_error_split.py: --region takes X0,X1,Y0,Y1 [m]\n");

  const auto bad = runScript(root / "drive", root / "bumped", "--windows 0 ");
  EXPECT_NE(bad.code, 0);
  EXPECT_EQ(bad.out, "trajectory_error_split.py: --windows must be a positive number of seconds\n");
}

TEST(TrajectoryErrorSplitScript, PassesTellTheStreetsAsFirstDrivenFromThoseDrivenAgain) {
  const fs::path root = bumpedLoop("trajectory_error_split_passes");
  // Edge a (0-11 s), b (12-17 s), a again (18-29 s: the pushed stretch), c (30-35 s).
  {
    std::ofstream csv(root / "drive/pose_edges.csv");
    csv << "index,t,sumo_edge,lane_pos_m\n";
    for (int t = 0; t < 36; ++t)
      csv << t << ',' << t << ','
          << (t < 12 || (t >= 18 && t < 30) ? "a"
              : t < 18                      ? "b"
                                            : "c")
          << ",0\n";
  }
  const auto r = runScript(root / "drive", root / "bumped", "--passes ");
  ASSERT_EQ(r.code, 0) << r.out;
  const auto line = r.out.find("first passes: RMS ");
  ASSERT_NE(line, std::string::npos) << r.out;
  const double first = std::stod(r.out.substr(line + 18));
  EXPECT_NE(r.out.find(" m on 66.7 % of the poses; later passes: RMS "), std::string::npos)
      << r.out;
  // A third of the poses 2 m aside: the alignment moves the whole estimate 2/3 m towards them,
  // leaving 2/3 m on the first passes and 4/3 m on the pushed stretch.
  EXPECT_NEAR(first, 2.0 / 3.0, 0.01) << r.out;
  const auto later = r.out.find("later passes: RMS ");
  EXPECT_NEAR(std::stod(r.out.substr(later + 18)), 4.0 / 3.0, 0.01) << r.out;

  fs::remove(root / "drive/pose_edges.csv");
  const auto missing = runScript(root / "drive", root / "bumped", "--passes ");
  EXPECT_NE(missing.code, 0);
  EXPECT_NE(missing.out.find(
                "trajectory_error_split.py: " + (root / "drive/pose_edges.csv").string() + ": "),
            std::string::npos)
      << missing.out;
  EXPECT_EQ(std::count(missing.out.begin(), missing.out.end(), '\n'), 1) << missing.out;
}

TEST(TrajectoryErrorSplitScript, AMissingOrMalformedTrajectoryIsOneLineNamingTheFile) {
  const fs::path root = slamroute::test::cliTempDir("trajectory_error_split_bad");
  fs::create_directories(root / "drive");
  fs::create_directories(root / "eval");
  writeLoop(root / "drive/groundtruth.tum", 1.0);

  const auto missing = runScript(root / "drive", root / "eval");
  EXPECT_NE(missing.code, 0);
  EXPECT_EQ(missing.out, "trajectory_error_split.py: " + (root / "eval/estimate.tum").string() +
                             ": no such file\n");

  std::ofstream(root / "eval/estimate.tum") << "0 1 2\n1 2 3\n";
  const auto malformed = runScript(root / "drive", root / "eval");
  EXPECT_NE(malformed.code, 0);
  EXPECT_NE(malformed.out.find((root / "eval/estimate.tum").string() + ": not a TUM trajectory"),
            std::string::npos)
      << malformed.out;
  EXPECT_EQ(std::count(malformed.out.begin(), malformed.out.end(), '\n'), 1) << malformed.out;
}

}  // namespace
