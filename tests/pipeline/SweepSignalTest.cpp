// A local `slamroute sweep` stopped by SIGTERM mid-run passes the signal on to its running steps
// (they stop and clean up; none goes on as an orphan), exits with 128 + 15 and leaves the tasks
// that finished stamped: `--resume` completes the study with the rows of an uninterrupted sweep.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include "SweepTestUtil.hpp"

namespace slamroute {
namespace {
namespace fs = std::filesystem;
using test::csvLines;
using test::readText;

/// Live (not zombie) processes whose command line mentions `text`.
std::vector<int> processesMentioning(const std::string& text) {
  std::vector<int> pids;
  for (const auto& e : fs::directory_iterator("/proc")) {
    const std::string name = e.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    std::string cmdline = readText(e.path() / "cmdline");
    for (char& c : cmdline)
      if (c == '\0') c = ' ';
    if (cmdline.find(text) != std::string::npos && !test::processDead(std::stol(name)))
      pids.push_back(std::stoi(name));
  }
  return pids;
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

/// Starts `slamroute sweep SPEC --out OUT --jobs 2 [--resume]` with its output in LOG.
pid_t startSweep(const fs::path& spec, const fs::path& out, const fs::path& log) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    const std::string cmd = std::string("exec ") + SLAMROUTE_BINARY + " sweep " + spec.string() +
                            " --out " + out.string() + " --jobs 2 > " + log.string() + " 2>&1";
    ::execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  return pid;
}

TEST(SweepSignal, ASweepStoppedBySigtermLeavesNoOrphanAndResumesToTheSameRows) {
  const auto dir = test::cliTempDir("sweep_sigterm");
  const fs::path spec = test::writeSpec(dir), out = dir / "stopped", log = dir / "stopped.log";
  const pid_t sweep = startSweep(spec, out, log);
  // Mid-run: a task has finished (its stamp kept) and another runs.
  ASSERT_TRUE(test::waitFor(
      [&] {
        const std::string text = readText(log);
        return count(text, "finished ") >= 1 && count(text, "started  ") > count(text, "finished ");
      },
      600))
      << readText(log);
  const std::vector<int> running = processesMentioning(out.string());
  ASSERT_GT(running.size(), 1u) << "no step runs beside the sweep";
  ::kill(sweep, SIGTERM);
  int status = 0;
  ASSERT_EQ(::waitpid(sweep, &status, 0), sweep);
  ASSERT_TRUE(WIFEXITED(status)) << "the sweep died of the signal instead of handling it";
  EXPECT_EQ(WEXITSTATUS(status), 128 + SIGTERM) << readText(log);
  EXPECT_NE(readText(log).find("--resume continues"), std::string::npos) << readText(log);
  EXPECT_TRUE(processesMentioning(out.string()).empty()) << "a step outlived the sweep";
  EXPECT_NE(readText(out / "failed_tasks.txt").find("not finished"), std::string::npos);

  const auto resumed =
      test::runCli("sweep " + spec.string() + " --out " + out.string() + " --jobs 2 --resume");
  ASSERT_EQ(resumed.code, 0) << resumed.out;
  EXPECT_NE(resumed.out.find("kept "), std::string::npos) << resumed.out;
  const auto whole =
      test::runCli("sweep " + spec.string() + " --out " + (dir / "whole").string() + " --jobs 2");
  ASSERT_EQ(whole.code, 0) << whole.out;
  const auto rows = csvLines(out / "results.csv");
  ASSERT_EQ(rows.size(), 3u) << readText(out / "results.csv");
  EXPECT_EQ(rows, csvLines(dir / "whole" / "results.csv"));
}

}  // namespace
}  // namespace slamroute
