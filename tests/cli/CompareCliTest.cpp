// `slamroute compare`: metrics for two trajectory files, one-line errors on bad input.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include "TestTmp.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

namespace {
namespace fs = std::filesystem;

struct CmdRun {
  int code = -1;
  std::string out;  ///< stdout
  std::string err;  ///< stderr
};

fs::path tmp() {
  fs::path d = slamroute::test::testTmp() / "compare_cli";
  fs::create_directories(d);
  return d;
}

CmdRun runCompare(const std::string& args) {
  // One file per test: ctest runs the tests of this file in parallel processes.
  const fs::path err =
      tmp() /
      (std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + ".stderr");
  const std::string cmd = std::string(SLAMROUTE_BINARY) + " " + args + " 2>" + err.string();
  CmdRun r;
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return r;
  std::array<char, 4096> buf{};
  std::size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), p)) > 0) r.out.append(buf.data(), n);
  const int status = pclose(p);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream e(err);
  r.err.assign(std::istreambuf_iterator<char>(e), {});
  return r;
}

/// A 300 m straight TUM trajectory; `stretch` scales the x coordinate.
fs::path writeTum(const std::string& name, double stretch, double t0 = 0.0) {
  const fs::path p = tmp() / name;
  std::ofstream f(p);
  f << "# t tx ty tz qx qy qz qw\n";
  for (int i = 0; i <= 300; ++i) f << t0 + 0.1 * i << " " << i * stretch << " 0 0 0 0 0 1\n";
  return p;
}

int lines(const std::string& s) {
  int n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

TEST(CompareCli, JsonOfAStretchedCopy) {
  const fs::path gt = writeTum("gt.tum", 1.0), est = writeTum("est.tum", 1.02);
  const CmdRun r =
      runCompare("compare " + est.string() + " " + gt.string() + " --json --segment 50");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["rpe_trans_pct"].get<double>(), 2.0, 1e-3);
  EXPECT_NEAR(j["rpe_segment_trans_pct"].get<double>(), 2.0, 1e-3);
  EXPECT_EQ(j["rpe_segment_m"].get<double>(), 50.0);
  EXPECT_EQ(j["poses_matched"].get<int>(), 301);
  EXPECT_NEAR(j["route_length_m"].get<double>(), 300.0, 1e-6);
  EXPECT_GT(j["ate_rmse_m"].get<double>(), 0.0);
}

TEST(CompareCli, IdenticalFilesGiveZeroTextReport) {
  const fs::path gt = writeTum("gt2.tum", 1.0);
  const CmdRun r = runCompare("compare " + gt.string() + " " + gt.string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("rmse 0.0000 m"), std::string::npos) << r.out;
}

TEST(CompareCli, MissingFileIsAOneLineError) {
  const fs::path gt = writeTum("gt3.tum", 1.0);
  const CmdRun r =
      runCompare("compare " + (tmp() / "does_not_exist.tum").string() + " " + gt.string());
  EXPECT_NE(r.code, 0);
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("does_not_exist.tum"), std::string::npos) << r.err;
}

TEST(CompareCli, MalformedLineIsAOneLineError) {
  const fs::path gt = writeTum("gt4.tum", 1.0);
  const fs::path bad = tmp() / "bad.tum";
  std::ofstream(bad) << "0.0 1 2 3 0 0 0 1\n0.1 1 2 three 0 0 0 1\n";
  const CmdRun r = runCompare("compare " + bad.string() + " " + gt.string());
  EXPECT_NE(r.code, 0);
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("bad.tum"), std::string::npos) << r.err;
}

TEST(CompareCli, DisjointTimestampsAreAOneLineError) {
  const fs::path gt = writeTum("gt5.tum", 1.0), est = writeTum("late.tum", 1.0, 1000.0);
  const CmdRun r = runCompare("compare " + est.string() + " " + gt.string());
  EXPECT_NE(r.code, 0);
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("associated"), std::string::npos) << r.err;
}

}  // namespace
