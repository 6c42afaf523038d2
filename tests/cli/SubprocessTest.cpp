// The pipeline's step runner quotes the last line of a child's log: when a step fails (the error
// message) and while it runs (its progress). Progress lines of a terminal use '\r'.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "Subprocess.hpp"
#include "TestTmp.hpp"

namespace slamroute::cli {
namespace {

std::filesystem::path writeLog(const std::string& name, const std::string& text) {
  const auto dir = test::testTmp();
  std::filesystem::create_directories(dir);
  const auto p = dir / name;
  std::ofstream(p, std::ios::binary) << text;
  return p;
}

TEST(Subprocess, LastLogLineSkipsBlankLinesAndKeepsTheLastProgressUpdate) {
  const auto p = writeLog("a.log",
                          "world: 10 buildings\nevaluate: SLAM  10.0% (1/10) 0.5 s\r"
                          "evaluate: SLAM  20.0% (2/10) 1.0 s\n  \n\n");
  EXPECT_EQ(lastLogLine(p), "evaluate: SLAM  20.0% (2/10) 1.0 s");
}

TEST(Subprocess, LastLogLineReadsOnlyTheEndAndNeverQuotesACutLine) {
  std::string text;
  for (int i = 0; i < 1000; ++i) text += "line " + std::to_string(i) + "\n";
  const auto p = writeLog("b.log", text);
  EXPECT_EQ(lastLogLine(p, 64), "line 999");
  // A window that holds only the tail of one line: nothing whole to quote.
  const auto q = writeLog("c.log", std::string(100, 'x') + "\n");
  EXPECT_EQ(lastLogLine(q, 50), "");
  EXPECT_EQ(lastLogLine(q), std::string(100, 'x'));
}

TEST(Subprocess, LastLogLineOfAMissingOrEmptyLogIsEmpty) {
  EXPECT_EQ(lastLogLine(test::testTmp() / "missing.log"), "");
  EXPECT_EQ(lastLogLine(writeLog("empty.log", "")), "");
}

}  // namespace
}  // namespace slamroute::cli
