// The README's commands: scripts/run_default.sh must call the program scripts/build.sh builds.
// (It called ./build/slamroute from the first commit on, while CMake builds build/cli/slamroute.)
#include "CliTestUtil.hpp"
#include "slamroute/core/AtomicFile.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <string>

namespace fs = std::filesystem;
using slamroute::readFile;

TEST(Scripts, RunDefaultCallsTheBuiltProgram) {
  const fs::path script = fs::path(SLAMROUTE_SOURCE_DIR) / "scripts" / "run_default.sh";
  const std::string text = readFile(script);
  ASSERT_FALSE(text.empty()) << script;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(text, m, std::regex(R"(\nbin=\./build/(\S+)\n)")))
      << script << " has no line bin=./build/...";
  ASSERT_NE(text.find("\"$bin\" run "), std::string::npos) << script << " does not run $bin";
  // scripts/build.sh builds into ./build; this suite's build folder is the parent of test_tmp.
  const fs::path build_dir = fs::path(SLAMROUTE_TEST_TMP_ROOT).parent_path();
  const fs::path expected = fs::weakly_canonical(build_dir / m[1].str());
  EXPECT_EQ(expected, fs::weakly_canonical(fs::path(SLAMROUTE_BINARY)));
  EXPECT_TRUE(fs::exists(expected)) << expected;
}

TEST(Scripts, TestScriptRunsCtestOnTheBuildFolder) {
  const std::string text = readFile(fs::path(SLAMROUTE_SOURCE_DIR) / "scripts" / "test.sh");
  EXPECT_NE(text.find("bash scripts/setup.sh"), std::string::npos);
  EXPECT_NE(text.find("bash scripts/build.sh"), std::string::npos);
  EXPECT_NE(text.find("ctest --test-dir build"), std::string::npos);
  const std::string ci = readFile(fs::path(SLAMROUTE_SOURCE_DIR) / ".ci" / "run");
  EXPECT_NE(ci.find("bash scripts/test.sh"), std::string::npos)
      << ".ci/run must call the README's test command";
}
