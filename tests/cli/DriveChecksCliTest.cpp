// `slamroute evaluate` on a drive whose files disagree (one cut short, one shuffled): a one-line
// error naming the file before any SLAM, a non-zero exit and no output folder.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <vector>

#include "CliTestUtil.hpp"
#include "slamroute/core/AtomicFile.hpp"

namespace slamroute {
namespace {
namespace fs = std::filesystem;

const std::string kGrid = std::string(SLAMROUTE_SOURCE_DIR) + "/networks/test/grid3x3.net.xml";

std::vector<std::string> lines(const fs::path& p) {
  std::istringstream in(readFile(p));
  std::vector<std::string> out;
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

void writeLines(const fs::path& p, const std::vector<std::string>& ls) {
  std::ofstream out(p);
  for (const auto& l : ls) out << l << "\n";
}

/// The first `keep` share of the file's lines.
void cut(const fs::path& p, double keep) {
  auto ls = lines(p);
  ls.resize(static_cast<std::size_t>(static_cast<double>(ls.size()) * keep));
  writeLines(p, ls);
}

TEST(DriveChecksCli, EvaluateRejectsDriveFilesThatDisagree) {
  const auto dir = test::cliTempDir("drive_checks");
  std::ofstream(dir / "route.json") << R"(["g00_g01","g01_g11"])";
  const auto d = test::runCli("drive --net " + kGrid + " --route " + (dir / "route.json").string() +
                              " --out " + (dir / "good").string() +
                              " --no-mesh --save-scans --log-level warn");
  ASSERT_EQ(d.code, 0) << d.out;
  struct Case {
    std::string name, file, fragment;
    void (*mutate)(const fs::path&);
  };
  const std::vector<Case> cases = {
      {"odo_half", "odometry.csv", "(file cut short?)", [](const fs::path& p) { cut(p, 0.5); }},
      {"times_cut", "scans/times.txt", "(file cut short?)", [](const fs::path& p) { cut(p, 0.3); }},
      {"gt_shuffled", "groundtruth.tum", "is not later than the pose before",
       [](const fs::path& p) {
         auto ls = lines(p);
         std::swap(ls[5], ls[ls.size() - 3]);
         writeLines(p, ls);
       }},
      {"edges_cut", "pose_edges.csv", "(file cut short?)", [](const fs::path& p) { cut(p, 0.6); }},
      {"edges_missing_row", "pose_edges.csv", "rows for",
       [](const fs::path& p) {
         auto ls = lines(p);
         ls.erase(ls.begin() + 4);
         writeLines(p, ls);
       }},
  };
  for (const auto& c : cases) {
    const fs::path drive = dir / c.name;
    fs::copy(dir / "good", drive, fs::copy_options::recursive);
    c.mutate(drive / c.file);
    const auto r = test::runCli("--log-level warn evaluate --drive " + drive.string() + " --out " +
                                (dir / (c.name + "_eval")).string());
    EXPECT_NE(r.code, 0) << c.name << "\n" << r.out;
    EXPECT_EQ(test::countLines(r.out), 1) << c.name << "\n" << r.out;
    EXPECT_NE(r.out.find((drive / c.file).string() + ":"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find(c.fragment), std::string::npos) << r.out;
    EXPECT_FALSE(fs::exists(dir / (c.name + "_eval"))) << c.name;
  }
}

}  // namespace
}  // namespace slamroute
