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

// Every script under bench/ (a file with a #! line; the others are its shared modules) answers
// --help with its description and exit 0, and a call without arguments with a usage line and a
// non-zero exit, never a Python traceback.
TEST(Scripts, EveryBenchScriptAnswersHelpAndACallWithoutArguments) {
  int scripts = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(SLAMROUTE_SOURCE_DIR) / "bench")) {
    if (entry.path().extension() != ".py" || readFile(entry.path()).rfind("#!", 0) != 0) continue;
    ++scripts;
    const std::string run = "/usr/bin/python3 " + entry.path().string();
    const slamroute::test::CliResult help = slamroute::test::runCommand(run + " --help");
    EXPECT_EQ(help.code, 0) << entry.path() << ": " << help.out;
    EXPECT_NE(help.out.find("sage"), std::string::npos) << entry.path() << ": " << help.out;
    const slamroute::test::CliResult bare = slamroute::test::runCommand(run);
    EXPECT_NE(bare.code, 0) << entry.path() << ": " << bare.out;
    EXPECT_NE(bare.out.find("sage"), std::string::npos) << entry.path() << ": " << bare.out;
    EXPECT_EQ(bare.out.find("Traceback"), std::string::npos) << entry.path() << ": " << bare.out;
  }
  EXPECT_GE(scripts, 15);
}

// The shell scripts under bench/ (with a #! line; script_help.sh is sourced) answer --help with
// their leading comment block, which names the script in its usage line, and exit 0 without
// running anything.
TEST(Scripts, EveryBenchShellScriptAnswersHelp) {
  int scripts = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(SLAMROUTE_SOURCE_DIR) / "bench")) {
    if (entry.path().extension() != ".sh" || readFile(entry.path()).rfind("#!", 0) != 0) continue;
    ++scripts;
    const slamroute::test::CliResult help =
        slamroute::test::runCommand("bash " + entry.path().string() + " --help");
    EXPECT_EQ(help.code, 0) << entry.path() << ": " << help.out;
    EXPECT_NE(help.out.find("bench/" + entry.path().filename().string()), std::string::npos)
        << entry.path() << ": " << help.out;
    EXPECT_EQ(help.out.find("#"), std::string::npos) << entry.path() << ": " << help.out;
  }
  EXPECT_GE(scripts, 7);
}
