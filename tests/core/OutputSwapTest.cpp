// Outputs that must not be lost: a result folder is swapped in so one complete result exists at
// every instant, a kill in the middle of the swap is repaired by the next run, a signal removes
// the staging folder, and several files are replaced together or not at all.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <string>
#include <vector>

#include "TestUtil.hpp"
#include "slamroute/core/AtomicFile.hpp"
#include "slamroute/core/StagingDir.hpp"

namespace slamroute {
namespace {
namespace fs = std::filesystem;

std::vector<std::string> entries(const fs::path& dir) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(dir)) out.push_back(e.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

/// A pid that belonged to a process that has exited.
pid_t deadPid() {
  const pid_t pid = ::fork();
  if (pid == 0) ::_exit(0);
  ::waitpid(pid, nullptr, 0);
  return pid;
}

void makeResult(const fs::path& dir, const std::string& content) {
  fs::create_directories(dir);
  test::writeText(dir / "metrics.json", content);
}

TEST(StagingDir, CommitReplacesTheOldResultAndLeavesNothingElse) {
  const auto dir = test::tempDir("staging_swap");
  makeResult(dir / "out", "old");
  {
    StagingDir s(dir / "out", "metrics.json");
    test::writeText(s.path() / "metrics.json", "new");
    s.commit();
  }
  EXPECT_EQ(readFile(dir / "out" / "metrics.json"), "new");
  EXPECT_EQ(entries(dir), std::vector<std::string>{"out"});
}

TEST(StagingDir, AResultSetAsideByAKilledSwapIsPutBack) {
  // The moment between "old result renamed aside" and "new one renamed in" (file systems without
  // RENAME_EXCHANGE), frozen by SIGKILL: only the aside folder holds a complete result.
  const auto dir = test::tempDir("staging_killed_swap");
  const pid_t dead = deadPid();
  makeResult(dir / (".out.old." + std::to_string(dead)), "old");
  makeResult(dir / (".out.tmp." + std::to_string(dead)), "half");
  {
    StagingDir s(dir / "out", "metrics.json");
    EXPECT_EQ(readFile(dir / "out" / "metrics.json"), "old");  // put back before any work
    // (a failed run: destroyed without commit)
  }
  EXPECT_EQ(readFile(dir / "out" / "metrics.json"), "old");
  EXPECT_EQ(entries(dir), std::vector<std::string>{"out"});
}

TEST(StagingDir, ASignalRemovesTheStagingFolder) {
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
    const auto dir = test::tempDir("staging_signal");
    const pid_t pid = ::fork();
    if (pid == 0) {
      StagingDir s(dir / "out", "metrics.json");
      fs::create_directories(s.path() / "scans");
      test::writeText(s.path() / "scans" / "000000.bin", std::string(100000, 'x'));
      ::raise(sig);
      ::_exit(0);  // not reached: the signal ends the process
    }
    int status = 0;
    ::waitpid(pid, &status, 0);
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == sig) << "signal " << sig;
    EXPECT_TRUE(entries(dir).empty()) << "signal " << sig << ": " << entries(dir).front();
  }
}

TEST(AtomicFileSet, ReplacesAllFilesOrNone) {
  const auto dir = test::tempDir("file_set");
  writeFileAtomic(dir / "g.json", "old json");
  writeFileAtomic(dir / "g.png", "old png");
  writeFileAtomic(dir / "g.rou.xml", "old companion");
  {
    AtomicFileSet files;
    writeFileAtomic(files.staged(dir / "g.json"), "new json");
    files.staged(dir / "g.png");  // its writer failed (a full disk): never written
    EXPECT_THROW(files.commit(), std::runtime_error);
  }
  EXPECT_EQ(readFile(dir / "g.json"), "old json");
  EXPECT_EQ(readFile(dir / "g.png"), "old png");
  EXPECT_EQ(entries(dir), (std::vector<std::string>{"g.json", "g.png", "g.rou.xml"}));
  {
    AtomicFileSet files;
    writeFileAtomic(files.staged(dir / "g.json"), "new json");
    writeFileAtomic(files.staged(dir / "g.png"), "new png");
    files.dropAtCommit(dir / "g.rou.xml");
    files.commit();
  }
  EXPECT_EQ(readFile(dir / "g.json"), "new json");
  EXPECT_EQ(readFile(dir / "g.png"), "new png");
  EXPECT_EQ(entries(dir), (std::vector<std::string>{"g.json", "g.png"}));
  // A folder is no file to replace: one line naming it.
  fs::create_directories(dir / "folder.json");
  try {
    writeFileAtomic(dir / "folder.json", "x");
    FAIL() << "wrote over a folder";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()),
              (dir / "folder.json").string() + ": is a folder; give a file name to write");
  }
}

}  // namespace
}  // namespace slamroute
