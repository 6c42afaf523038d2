// End to end: `slamroute run` on the plus-shaped test net (survey -> graph -> plan x3 -> drive
// x3 -> LiDAR SLAM x3 -> report). Every 5th scan keeps it to ~20 s.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>

#include <nlohmann/json.hpp>

#include "CliTestUtil.hpp"
#include "slamroute/core/AtomicFile.hpp"

namespace slamroute {
namespace {

/// Starts `slamroute ARGS` in the background, its output going to `log`; returns its pid.
pid_t spawnCli(const std::string& args, const std::filesystem::path& log) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    const std::string cmd =
        "exec " + std::string(SLAMROUTE_BINARY) + " " + args + " > " + log.string() + " 2>&1";
    ::execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  return pid;
}

std::string readText(const std::filesystem::path& p) {
  std::ifstream in(p);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

/// Whether a running process has `text` in its command line.
bool processMentions(const std::string& text) {
  for (const auto& e : std::filesystem::directory_iterator("/proc")) {
    const std::string name = e.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    std::string cmdline = readText(e.path() / "cmdline");
    std::replace(cmdline.begin(), cmdline.end(), '\0', ' ');
    if (std::to_string(::getpid()) != name && cmdline.find(text) != std::string::npos) return true;
  }
  return false;
}

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

/// Each planner's route, drive, SLAM estimate, metrics and map.pcd.
void expectEveryPlannersOutputs(const std::filesystem::path& out) {
  for (const std::string p : {"qlearning", "random", "postman"}) {
    EXPECT_TRUE(std::filesystem::exists(out / "routes" / (p + ".rou.xml"))) << p;
    EXPECT_TRUE(std::filesystem::exists(out / "drives" / p / "groundtruth.tum")) << p;
    EXPECT_TRUE(std::filesystem::exists(out / "eval" / p / "estimate.tum")) << p;
    const auto m = nlohmann::json::parse(readFile(out / "eval" / p / "metrics.json"));
    for (const char* k : {"ate_rmse_m", "ate_mean_m", "ate_max_m", "rpe_trans_pct",
                          "coverage_edge_pct", "route_length_m", "loop_closures"})
      EXPECT_TRUE(m.contains(k)) << p << " lacks " << k;
    // The yaw prior scales with the drive's gyro (odometry.yaml) against the reference 0.1 / 0.05
    // deg/s.
    EXPECT_NEAR(m.value("odometry_prior_sigma_deg", 0.0),
                0.02 * std::hypot(0.2, 0.05) / std::hypot(0.1, 0.05), 1e-9)
        << p;
    const auto route = nlohmann::json::parse(readFile(out / "routes" / (p + ".json")));
    EXPECT_GT(route["length_m"].get<double>(), 100.0) << p;
    // map.pcd, written tile by tile, holds the map_points that metrics.json counts, and the map
    // accuracy measured them all.
    const std::string pcd = readFile(out / "eval" / p / "map.pcd");
    const auto n = m["map_points"].get<std::size_t>();
    EXPECT_GT(n, 1000u) << p;
    EXPECT_NE(pcd.find("\nPOINTS " + std::to_string(n) + "\nDATA binary\n"), std::string::npos)
        << p;
    EXPECT_EQ(pcd.size(), pcd.find("DATA binary\n") + 12 + 12 * n) << p;
    EXPECT_TRUE(m["map_median_dist_m"].is_number()) << p;
  }
}

/// The random walk's budget and the directed coverage of the postman route.
void expectBudgetAndDirectedCoverage(const std::filesystem::path& out) {
  // The random walk is given the Q-learning route's length as its budget.
  const auto q = nlohmann::json::parse(readFile(out / "routes" / "qlearning.json"));
  const auto rnd = nlohmann::json::parse(readFile(out / "routes" / "random.json"));
  EXPECT_LT(rnd["length_m"].get<double>(), q["length_m"].get<double>() + 200.0);
  // Directed coverage of the net's SUMO edges, planned (route.json) and as driven (metrics.json):
  // postman drives every direction of every street of the plus net (8 directed edges).
  const auto pm = nlohmann::json::parse(readFile(out / "routes" / "postman.json"));
  const auto pd = nlohmann::json::parse(readFile(out / "eval" / "postman" / "metrics.json"));
  EXPECT_EQ(pm["directed_coverage"]["edges_total"].get<int>(), 8);
  EXPECT_DOUBLE_EQ(pm["directed_coverage"]["edges_pct"].get<double>(), 100.0);
  EXPECT_DOUBLE_EQ(pd["directed_coverage"]["edges_pct"].get<double>(), 100.0);
  EXPECT_GT(pm["sumo_length"]["in_junctions_m"].get<double>(), 0.0);
}

/// report.md: the tables of every planner and step, and the map accuracy cell.
void expectReportTables(const std::filesystem::path& out) {
  const std::string report = readFile(out / "report.md");
  for (const char* s :
       {"| qlearning |", "| random |", "| postman |", "Spearman", "report/graph_weights.png",
        "| node recall | ", "| survey | value | meaning |", "| streets driven | ",
        "| sumo_mapping | value | meaning |", "| turns forbidden | ",
        "| noise correlation time | 2.0 s | ", "| directed SUMO edges [%] |"})
    EXPECT_NE(report.find(s), std::string::npos) << s;
  EXPECT_TRUE(std::filesystem::exists(out / "report" / "route_qlearning.png"));
  // Drift per street kind, along the street and end to end, a number in every cell.
  const std::string kinds =
      "| street kind | driven [km] | drift along the street [%] | drift end to end [%] |\n"
      "|---|---|---|---|\n";
  const std::size_t table = report.find(kinds);
  ASSERT_NE(table, std::string::npos) << report;
  const std::string rows =
      report.substr(table + kinds.size(), report.find("\n\n", table) - table - kinds.size());
  EXPECT_FALSE(rows.empty());
  EXPECT_EQ(rows.find("–"), std::string::npos) << rows;
  // Map accuracy: the median distance and the share beyond the 2 m clamp, from metrics.json (a
  // p95 of clamped distances was always the clamp).
  const auto mq = nlohmann::json::parse(readFile(out / "eval" / "qlearning" / "metrics.json"));
  // A median with half the points or more beyond the clamp is the clamp: written "> 2.0".
  auto median = [&](const char* prefix) {
    char buf[32];
    const std::string p = prefix;
    if (mq[p + "far_share"].get<double>() >= 0.5) return std::string("> 2.0");
    std::snprintf(buf, sizeof buf, "%.2f", mq[p + "median_dist_m"].get<double>());
    return std::string(buf);
  };
  char cell[96];
  std::snprintf(cell, sizeof cell, "| %s / %.1f (> 2.0 m) | %s / %.1f (> 2.0 m) |",
                median("map_").c_str(), 100.0 * mq["map_far_share"].get<double>(),
                median("map_aligned_").c_str(), 100.0 * mq["map_aligned_far_share"].get<double>());
  EXPECT_NE(report.find(cell), std::string::npos) << cell << "\n" << report;
  EXPECT_TRUE(std::filesystem::exists(out / "eval" / "qlearning" / "map_error_top.png"));
  EXPECT_NE(report.find("eval/qlearning/map_error_top.png"), std::string::npos);
}

/// A second run with --resume keeps all steps and writes only the report again.
void expectResumeKeepsEveryStep(const std::string& cmd, const std::filesystem::path& out) {
  // --resume: every step left its stamp, so a second run keeps all eleven (survey, graph, three
  // plans, drives and SLAM runs) and only writes the report again.
  for (const std::string step :
       {"survey", "build-graph", "plan-random", "drive-postman", "evaluate-qlearning"})
    EXPECT_TRUE(std::filesystem::exists(out / "logs" / (step + ".done"))) << step;
  const std::string metrics_q = readFile(out / "eval" / "qlearning" / "metrics.json");
  const auto again = test::runCli(cmd + " --resume");
  ASSERT_EQ(again.code, 0) << again.out;
  EXPECT_EQ(count(again.out, "  kept     "), 11) << again.out;
  EXPECT_EQ(count(again.out, "  started  "), 0) << again.out;
  EXPECT_EQ(readFile(out / "eval" / "qlearning" / "metrics.json"), metrics_q);
  const std::string report2 = readFile(out / "report.md");
  EXPECT_NE(report2.find("| evaluate postman | kept from an earlier run |"), std::string::npos)
      << report2;
  EXPECT_NE(report2.find("--resume"), std::string::npos);
  EXPECT_NE(report2.find("s (this run; 11 of 11 steps kept from an earlier one)"),
            std::string::npos)
      << report2;
}

/// A resumed run that must redo the SLAM, stopped by SIGTERM, then resumed to the end.
void expectSigtermStopsTheSlamAndResumeFinishes(const std::string& cmd,
                                                const std::filesystem::path& dir,
                                                const std::filesystem::path& out) {
  // Without the SLAM outputs, a resumed run does only the SLAM. Stopped by SIGTERM (a job
  // scheduler) while the SLAM runs, it stops them too, exits with 128 + 15 and leaves no
  // process behind; the next --resume does the SLAM runs that did not finish.
  const std::string estimate_q = readFile(out / "eval" / "qlearning" / "estimate.tum");
  std::filesystem::remove_all(out / "eval");
  const auto log = dir / "interrupted.log";
  const pid_t pid = spawnCli(cmd + " --resume", log);
  ASSERT_GT(pid, 0);
  for (int i = 0; i < 3000 && readText(log).find("  started  evaluate") == std::string::npos; ++i)
    ::usleep(10000);
  ::usleep(200000);  // the SLAM runs are under way
  ::kill(pid, SIGTERM);
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  const std::string stopped = readText(log);
  ASSERT_TRUE(WIFEXITED(status)) << stopped;
  EXPECT_EQ(WEXITSTATUS(status), 128 + SIGTERM) << stopped;
  EXPECT_NE(stopped.find("slamroute: interrupted by "), std::string::npos) << stopped;
  EXPECT_NE(stopped.find("; stopped evaluate "), std::string::npos) << stopped;
  EXPECT_EQ(count(stopped, "  started  "), 3) << stopped;  // the SLAM runs only
  EXPECT_FALSE(processMentions(out.string())) << "a step outlived the stopped run";
  int finished = 0;
  for (const std::string p : {"qlearning", "random", "postman"})
    finished += std::filesystem::exists(out / "logs" / ("evaluate-" + p + ".done"));
  EXPECT_LT(finished, 3);
  const auto redo = test::runCli(cmd + " --resume");
  ASSERT_EQ(redo.code, 0) << redo.out;
  EXPECT_EQ(count(redo.out, "  started  "), 3 - finished) << redo.out;
  for (const std::string p : {"qlearning", "random", "postman"})
    EXPECT_TRUE(std::filesystem::exists(out / "eval" / p / "metrics.json")) << p;
  EXPECT_EQ(readFile(out / "eval" / "qlearning" / "estimate.tum"),
            estimate_q);  // same seed, same output
}

TEST(RunCli, WholePipelineOnThePlusNet) {
  const auto dir = test::cliTempDir("run_plus");
  // A gyro twice as noisy as the default: evaluate must take its figures from odometry.yaml.
  std::ofstream(dir / "fast.yaml") << "evaluate:\n  input:\n    scan_stride: 5\nsimulate:\n  "
                                      "drive:\n    gyro_noise_deg_s: 0.2\n";
  const std::string cmd = "--config " + (dir / "fast.yaml").string() + " run --net " +
                          std::string(SLAMROUTE_SOURCE_DIR) + "/networks/test/plus.net.xml --out " +
                          (dir / "out").string() +
                          " --status-every 0.2 --planners qlearning,random,postman";
  const auto r = test::runCli(cmd);
  ASSERT_EQ(r.code, 0) << r.out;
  // While steps run, their progress is quoted from their logs now and then (here every 0.2 s):
  // "  running  evaluate postman [3 s]: evaluate: SLAM  40.0% ...".
  EXPECT_NE(r.out.find("  running  "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("s]: "), std::string::npos) << r.out;
  const auto out = dir / "out";
  expectEveryPlannersOutputs(out);
  expectBudgetAndDirectedCoverage(out);
  expectReportTables(out);
  expectResumeKeepsEveryStep(cmd, out);
  expectSigtermStopsTheSlamAndResumeFinishes(cmd, dir, out);
}

TEST(RunCli, BadNetIsAOneLineErrorAndWritesNothing) {
  const auto dir = test::cliTempDir("run_bad");
  const auto r = test::runCli("run --net " + (dir / "missing.net.xml").string() + " --out " +
                              (dir / "out").string());
  EXPECT_NE(r.code, 0);
  EXPECT_EQ(test::countLines(r.out), 1) << r.out;
  EXPECT_FALSE(std::filesystem::exists(dir / "out"));
}

}  // namespace
}  // namespace slamroute
