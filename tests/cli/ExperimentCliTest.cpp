// `slamroute experiment paper` end to end on the plus-shaped test net with one seed (survey ->
// graph -> three planned variants -> drives -> SLAM -> tables; ~12 s), then --resume.
#include <gtest/gtest.h>

#include <cstdio>
#include <nlohmann/json.hpp>

#include "CliTestUtil.hpp"
#include "slamroute/core/AtomicFile.hpp"

namespace slamroute {
namespace {
namespace fs = std::filesystem;

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

/// The row of `table` (text from its heading on) for `route`.
std::string row(const std::string& tables, const std::string& heading, const std::string& route) {
  const auto at = tables.find(heading);
  if (at == std::string::npos) return {};
  const auto r = tables.find("| " + route + " |", at);
  if (r == std::string::npos) return {};
  return tables.substr(r, tables.find('\n', r) - r);
}

TEST(ExperimentCli, PaperTablesOnThePlusNetAndResume) {
  const auto dir = test::cliTempDir("experiment_plus");
  std::ofstream(dir / "fast.yaml") << "evaluate:\n  input:\n    scan_stride: 5\n";
  const std::string net = std::string(SLAMROUTE_SOURCE_DIR) + "/networks/test/plus.net.xml";
  const std::string cmd =
      "--seed 42 --config " + (dir / "fast.yaml").string() + " experiment paper --net " + net +
      " --seeds 1 --sizes 20,30 --status-every 0 --out " + (dir / "out").string();
  const auto r = test::runCli(cmd);
  ASSERT_EQ(r.code, 0) << r.out;
  const fs::path out = dir / "out";
  const std::string tables = readFile(out / "paper_tables.md");
  // The command line reproduces the tables: net, config, seeds and sizes are all in it.
  EXPECT_NE(tables.find("Command: `slamroute --seed 42 --config " + (dir / "fast.yaml").string() +
                        " experiment paper --net " + net + " --out " + out.string() +
                        " --seeds 1 --sizes 20,30`"),
            std::string::npos)
      << tables;
  EXPECT_NE(tables.find("(mean ± std over 1 seed)"), std::string::npos);
  // Table 1's Q-learning row carries the SLAM run's ATE RMSE and the route's length.
  const auto m = nlohmann::json::parse(readFile(out / "eval" / "qlearning_s1" / "metrics.json"));
  const auto q = nlohmann::json::parse(readFile(out / "routes" / "qlearning_s1.json"));
  char ate[64], len[64];
  std::snprintf(ate, sizeof ate, "| %.3f ± 0.000 |", m["ate_rmse_m"].get<double>());
  std::snprintf(len, sizeof len, "| %.2f ± 0.00 |", q["length_m"].get<double>() / 1000.0);
  const std::string q1 = row(tables, "## Table 1", "qlearning");
  EXPECT_NE(q1.find(ate), std::string::npos) << q1 << " vs " << ate;
  EXPECT_NE(q1.find(len), std::string::npos) << q1 << " vs " << len;
  EXPECT_EQ(row(tables, "## Table 1", "random").find("–"), std::string::npos) << tables;
  EXPECT_EQ(row(tables, "## Table 2", "qlearning_accuracy").find("–"), std::string::npos) << tables;
  // The random walk drives as far as the Q-learning route (the budget), not farther.
  const auto rnd = nlohmann::json::parse(readFile(out / "routes" / "random_s1.json"));
  EXPECT_LT(rnd["length_m"].get<double>(), q["length_m"].get<double>() + 200.0);
  // Table 3: each planner on each size.
  for (const char* p : {"qlearning", "tsp", "postman"})
    for (const char* n : {" | 20 | ", " | 30 | "})
      EXPECT_NE(tables.find(std::string("| ") + p + n), std::string::npos) << p << n << "\n"
                                                                           << tables;

  // --resume keeps all eleven steps (survey, graph, three plans, drives, SLAM runs) and writes
  // the same tables.
  const auto again = test::runCli(cmd + " --resume");
  ASSERT_EQ(again.code, 0) << again.out;
  EXPECT_EQ(count(again.out, "  kept     "), 11) << again.out;
  EXPECT_EQ(count(again.out, "  started  "), 0) << again.out;
  const std::string tables2 = readFile(out / "paper_tables.md");
  EXPECT_EQ(row(tables2, "## Table 1", "qlearning"), q1);
  EXPECT_NE(tables2.find("--sizes 20,30 --resume`"), std::string::npos);
}

TEST(ExperimentCli, UnknownExperimentIsAnErrorAndWritesNothing) {
  const auto dir = test::cliTempDir("experiment_bad");
  const auto r = test::runCli("experiment tables --out " + (dir / "out").string());
  EXPECT_NE(r.code, 0) << r.out;
  EXPECT_FALSE(fs::exists(dir / "out"));
}

}  // namespace
}  // namespace slamroute
