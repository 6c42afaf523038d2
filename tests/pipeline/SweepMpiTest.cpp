// `slamroute sweep` end to end on the plus test net: under `mpirun -n 2` the rows come out equal
// to the same study run without MPI, and a worker rank killed mid-task has its task re-queued.
#include <gtest/gtest.h>

#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <thread>

#include "SweepTestUtil.hpp"

namespace slamroute {
namespace {
namespace fs = std::filesystem;
using test::csvLines;
using test::readText;
using test::writeSpec;

/// `mpirun -n RANKS slamroute sweep ...` on loopback (root allowed: CI containers run as root).
/// `recovery`: the job goes on when a rank dies (mpirun then exits 0 whatever rank 0 returns).
std::string mpirunSweep(int ranks, bool recovery, const fs::path& spec, const fs::path& out,
                        const std::string& extra) {
  return "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_btl=self,tcp "
         "OMPI_MCA_btl_tcp_if_include=lo mpirun --oversubscribe " +
         std::string(recovery ? "--enable-recovery " : "") + "-n " + std::to_string(ranks) + " " +
         SLAMROUTE_BINARY + " sweep " + spec.string() + " --out " + out.string() + " " + extra;
}

/// Why the MPI tests cannot run here; empty when they can.
std::string whyNoMpi() {
#ifndef SLAMROUTE_WITH_MPI
  return "slamroute built without MPI (scripts/setup.sh installs libopenmpi-dev)";
#endif
  if (test::runCommand("command -v mpirun").code != 0)
    return "mpirun not found (scripts/setup.sh installs openmpi-bin)";
  return "";
}

TEST(SweepMpi, TwoRanksGiveTheRowsOfALocalSweep) {
  if (const std::string why = whyNoMpi(); !why.empty()) GTEST_SKIP() << why;
  const auto dir = test::cliTempDir("sweep_mpi");
  const fs::path spec = writeSpec(dir);
  const auto mpi = test::runCommand(mpirunSweep(2, false, spec, dir / "mpi", ""));
  ASSERT_EQ(mpi.code, 0) << mpi.out;
  EXPECT_NE(mpi.out.find("on rank 1"), std::string::npos) << "rank 1 ran no task:\n" << mpi.out;
  const auto local =
      test::runCli("sweep " + spec.string() + " --out " + (dir / "local").string() + " --jobs 2");
  ASSERT_EQ(local.code, 0) << local.out;
  const auto a = csvLines(dir / "mpi" / "results.csv"), b = csvLines(dir / "local" / "results.csv");
  ASSERT_EQ(a.size(), 3u) << readText(dir / "mpi" / "results.csv");  // header + 2 rows
  EXPECT_EQ(a, b);
  EXPECT_NE(a[0].find("eval.ate_rmse_m"), std::string::npos) << a[0];
  EXPECT_EQ(a[1].rfind("plus,fast,qlearning,3,ok,", 0), 0u) << a[1];
  EXPECT_EQ(a[2].rfind("plus,fast,random,3,ok,", 0), 0u) << a[2];
  EXPECT_EQ(readText(dir / "mpi" / "failed_tasks.txt"), "");
  const std::string summary = readText(dir / "mpi" / "summary.md");
  EXPECT_NE(summary.find("| plus / fast / qlearning | 1 |"), std::string::npos) << summary;
  EXPECT_TRUE(fs::exists(dir / "mpi" / "summary" / "ate_rmse_m.png"));
  // --resume keeps every task: all 8 stamped.
  const auto again =
      test::runCli("sweep " + spec.string() + " --out " + (dir / "local").string() + " --resume");
  ASSERT_EQ(again.code, 0) << again.out;
  EXPECT_NE(again.out.find("8 tasks on 1 rank(s)"), std::string::npos) << again.out;
  EXPECT_NE(readText(dir / "local" / "summary.md").find("8 kept from an earlier sweep"),
            std::string::npos);
  EXPECT_EQ(csvLines(dir / "local" / "results.csv"), b);
}

TEST(SweepMpi, AKilledWorkersTaskIsRequeued) {
  if (const std::string why = whyNoMpi(); !why.empty()) GTEST_SKIP() << why;
  const auto dir = test::cliTempDir("sweep_kill");
  const fs::path spec = writeSpec(dir), out = dir / "out";
  const fs::path log = dir / "sweep.log";
  const std::string cmd =
      mpirunSweep(2, true, spec, out, "--worker-timeout 3") + " > " + log.string() + " 2>&1";
  std::thread sweep([&] { EXPECT_EQ(std::system(cmd.c_str()), 0) << readText(log); });
  // Once rank 1 runs a task, kill it (SIGKILL: no goodbye; rank 0 notices the silence).
  bool killed = false;
  for (int i = 0; i < 600 && !killed; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    const std::string pid = readText(out / "workers" / "rank1.pid");
    if (!pid.empty() && readText(log).find("on rank 1") != std::string::npos)
      killed = ::kill(std::stoi(pid), SIGKILL) == 0;
  }
  sweep.join();
  ASSERT_TRUE(killed) << readText(log);
  const std::string text = readText(log);
  EXPECT_NE(text.find("rank 1 silent for 3 s: taken for dead"), std::string::npos) << text;
  EXPECT_NE(text.find("re-queued"), std::string::npos) << text;
  const auto rows = csvLines(out / "results.csv");
  ASSERT_EQ(rows.size(), 3u) << readText(out / "results.csv");
  EXPECT_NE(rows[1].find(",ok,"), std::string::npos) << rows[1];
  EXPECT_NE(rows[2].find(",ok,"), std::string::npos) << rows[2];
  EXPECT_NE(readText(out / "summary.md").find("1 after a retry"), std::string::npos);
}

}  // namespace
}  // namespace slamroute
