// Progress: the terminal bar (rate, time left) and the one-line-per-update form of a log file.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>

#include "TestUtil.hpp"
#include "slamroute/core/Log.hpp"

namespace slamroute {
namespace {

TEST(Progress, BarShowsShareCountRateAndTimeLeft) {
  // 250 of 1000 in 10 s: 25 a second, 750 left -> 30 s.
  EXPECT_EQ(progressBar("survey", 250, 1000, 10.0, 20),
            "survey [#####...............]  25.0% 250/1000  25/s  30s left");
  EXPECT_EQ(progressBar("slam", 0, 10, 3.0, 4), "slam [....]   0.0% 0/10  0/s  ? left");
  EXPECT_EQ(progressBar("x", 10, 10, 2.0, 4), "x [####] 100.0% 10/10  5/s  0s left");
  EXPECT_EQ(progressBar("q", 15873, 20000, 1.0, 4),
            "q [###.]  79.4% 15873/20000  15873/s  0s left");
  EXPECT_EQ(formatDuration(187.0), "3m07s");
  EXPECT_EQ(formatDuration(7500.0), "2h05m");
  EXPECT_EQ(formatDuration(-1.0), "?");
}

TEST(Progress, WithoutATerminalEachUpdateIsOneLine) {
  const auto log = test::testTmp() / "progress.log";
  std::cerr.flush();
  const int saved = dup(STDERR_FILENO);
  const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  ASSERT_GE(fd, 0);
  dup2(fd, STDERR_FILENO);
  {
    Progress p("steps", 3);
    p.update(3);
    p.finish();
  }
  std::cerr.flush();
  dup2(saved, STDERR_FILENO);
  ::close(fd);
  ::close(saved);
  std::ifstream in(log);
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  EXPECT_EQ(text.find('\r'), std::string::npos);
  EXPECT_EQ(text.find('['), std::string::npos);
  EXPECT_EQ(text.rfind("steps 100.0% (3/3) ", 0), 0u) << text;
  EXPECT_NE(text.find("\nsteps done (3) in "), std::string::npos) << text;
}

}  // namespace
}  // namespace slamroute
