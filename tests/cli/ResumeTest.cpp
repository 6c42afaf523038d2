// `--resume` (cli/Resume.hpp): content hashes, step stamps, and which steps are kept.
#include <gtest/gtest.h>
#include "TestTmp.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "Resume.hpp"
#include "slamroute/core/AtomicFile.hpp"

namespace slamroute::cli {
namespace {
namespace fs = std::filesystem;

void put(const fs::path& p, const std::string& text) {
  fs::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << text;
}

TEST(Resume, FileHashFollowsTheBytesNotTheName) {
  const fs::path dir = test::testTmp();
  put(dir / "a.txt", "the same twelve bytes and a tail");
  put(dir / "b.txt", "the same twelve bytes and a tail");
  put(dir / "c.txt", "the same twelve bytes and a taiL");  // one byte differs, in the tail
  put(dir / "empty.txt", "");
  EXPECT_EQ(fileHash(dir / "a.txt"), fileHash(dir / "b.txt"));
  EXPECT_NE(fileHash(dir / "a.txt"), fileHash(dir / "c.txt"));
  EXPECT_NE(fileHash(dir / "empty.txt"), fileHash(dir / "a.txt"));
  // A file larger than the 1 MiB read buffer: a change in its second block counts.
  std::string big(3 << 20, 'x');
  put(dir / "big1.bin", big);
  big[(1 << 20) + 17] = 'y';
  put(dir / "big2.bin", big);
  EXPECT_NE(fileHash(dir / "big1.bin"), fileHash(dir / "big2.bin"));
  EXPECT_THROW(fileHash(dir / "missing.txt"), std::runtime_error);
}

TEST(Resume, FolderHashSeesContentNamesAndNewFiles) {
  const fs::path dir = test::testTmp();
  put(dir / "one" / "survey.json", "{}");
  put(dir / "one" / "depth" / "0001.png", "pixels");
  put(dir / "two" / "survey.json", "{}");
  put(dir / "two" / "depth" / "0001.png", "pixels");
  const auto h = folderHash(dir / "one");
  EXPECT_EQ(h, folderHash(dir / "two"));  // where the folder is does not matter
  put(dir / "two" / "depth" / "0001.png", "pixelz");
  EXPECT_NE(h, folderHash(dir / "two"));
  put(dir / "two" / "depth" / "0001.png", "pixels");
  EXPECT_EQ(h, folderHash(dir / "two"));
  fs::rename(dir / "two" / "depth" / "0001.png", dir / "two" / "depth" / "0002.png");
  EXPECT_NE(h, folderHash(dir / "two"));
  fs::rename(dir / "two" / "depth" / "0002.png", dir / "two" / "depth" / "0001.png");
  put(dir / "two" / "extra.csv", "");
  EXPECT_NE(h, folderHash(dir / "two"));
}

Step evaluateStep(const fs::path& dir, const std::string& seed, const std::string& level) {
  Step s;
  s.label = "evaluate p";
  s.args = {"--seed",
            seed,
            "--log-level",
            level,
            "--config",
            (dir / "c.yaml").string(),
            "evaluate",
            "--drive",
            (dir / "drive").string(),
            "--out",
            (dir / "eval").string()};
  s.log = dir / "logs" / "evaluate-p.log";
  s.output = dir / "eval" / "metrics.json";
  return s;
}

TEST(Resume, StampChangesWithArgumentsAndInputsButNotWithTheOutputOrLogLevel) {
  const fs::path dir = test::testTmp();
  put(dir / "c.yaml", "evaluate:\n  input:\n    scan_stride: 5\n");
  put(dir / "drive" / "groundtruth.tum", "0 0 0 0 0 0 0 1\n");
  put(dir / "eval" / "metrics.json", "{}");
  const std::string s0 = stepStamp(evaluateStep(dir, "42", "info"));
  EXPECT_NE(s0.find("slamroute "), std::string::npos);
  char program[40];  // the running program's content hash: another binary would run it again
  std::snprintf(program, sizeof program, "\nprogram %016llx\n",
                static_cast<unsigned long long>(fileHash("/proc/self/exe")));
  EXPECT_NE(s0.find(program), std::string::npos) << s0;
  EXPECT_EQ(s0, stepStamp(evaluateStep(dir, "42", "debug")));
  put(dir / "eval" / "metrics.json", "{\"ate_rmse_m\": 1}");  // the step's own output
  EXPECT_EQ(s0, stepStamp(evaluateStep(dir, "42", "info")));
  EXPECT_NE(s0, stepStamp(evaluateStep(dir, "7", "info")));
  put(dir / "c.yaml", "evaluate:\n  input:\n    scan_stride: 4\n");  // config content, same path
  const std::string s1 = stepStamp(evaluateStep(dir, "42", "info"));
  EXPECT_NE(s0, s1);
  put(dir / "drive" / "groundtruth.tum", "0 0 0 0 0 0 0 1\n1 1 0 0 0 0 0 1\n");  // an input folder
  EXPECT_NE(s1, stepStamp(evaluateStep(dir, "42", "info")));
}

TEST(Resume, KeepsOnlyStepsWithAnOutputAndTheSameStamp) {
  const fs::path dir = test::testTmp();
  put(dir / "c.yaml", "evaluate:\n  input:\n    scan_stride: 5\n");
  put(dir / "drive" / "groundtruth.tum", "0 0 0 0 0 0 0 1\n");
  const Step s = evaluateStep(dir, "42", "info");
  // Nothing done yet: it runs, stamped.
  auto left = stepsToRun({s}, true);
  ASSERT_EQ(left.size(), 1u);
  EXPECT_EQ(left[0].stamp, stepStamp(s));
  // Output and matching stamp (what runSteps writes when the step succeeds): kept.
  put(dir / "eval" / "metrics.json", "{}");
  writeFileAtomic(stampPath(s), stepStamp(s));
  EXPECT_EQ(stampPath(s), dir / "logs" / "evaluate-p.done");
  EXPECT_TRUE(stepsToRun({s}, true).empty());
  // Without --resume everything runs, still stamped.
  left = stepsToRun({s}, false);
  ASSERT_EQ(left.size(), 1u);
  EXPECT_FALSE(left[0].stamp.empty());
  // Another seed, or an input that changed since: it runs again.
  EXPECT_EQ(stepsToRun({evaluateStep(dir, "7", "info")}, true).size(), 1u);
  put(dir / "drive" / "odometry.csv", "t,v\n");
  EXPECT_EQ(stepsToRun({s}, true).size(), 1u);
  fs::remove(dir / "drive" / "odometry.csv");
  EXPECT_TRUE(stepsToRun({s}, true).empty());
  // A step without a declared output always runs.
  Step always = s;
  always.output.clear();
  EXPECT_EQ(stepsToRun({always}, true).size(), 1u);
  // An output without a stamp (a step that finished as the orphan of a killed run, with the
  // config it was started with) is made again.
  fs::remove(stampPath(s));
  EXPECT_EQ(stepsToRun({s}, true).size(), 1u);
}

TEST(Resume, ACopiedRunFolderKeepsItsSteps) {
  const fs::path dir = test::testTmp();
  put(dir / "a" / "c.yaml", "evaluate:\n  input:\n    scan_stride: 5\n");
  put(dir / "a" / "drive" / "groundtruth.tum", "0 0 0 0 0 0 0 1\n");
  put(dir / "a" / "eval" / "metrics.json", "{}");
  const Step s = evaluateStep(dir / "a", "42", "info");
  writeFileAtomic(stampPath(s), stepStamp(s));
  fs::copy(dir / "a", dir / "b", fs::copy_options::recursive);
  EXPECT_TRUE(stepsToRun({evaluateStep(dir / "b", "42", "info")}, true).empty());
  put(dir / "b" / "drive" / "groundtruth.tum", "0 0 0 0 0 0 0 1\n1 1 0 0 0 0 0 1\n");
  EXPECT_EQ(stepsToRun({evaluateStep(dir / "b", "42", "info")}, true).size(), 1u);
}

}  // namespace
}  // namespace slamroute::cli
