// metrics.json through the typed EvaluationResult: a file `slamroute evaluate` wrote (a 40 s drive
// on the plus net, with loop closures, drift per street kind and map accuracy) reads back and
// writes the same bytes, and the figures a sweep tabulates are the file's numbers.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "TestTmp.hpp"
#include "slamroute/core/AtomicFile.hpp"
#include "slamroute/evaluate/EvaluationResult.hpp"

namespace slamroute::evaluate {
namespace {
namespace fs = std::filesystem;

const fs::path kDriveMetrics =
    fs::path(SLAMROUTE_SOURCE_DIR) / "tests/evaluate/data/metrics_plus_drive.json";

/// Every number and bool of `j` below objects (arrays skipped), by its dotted key.
void numbersOf(const nlohmann::json& j, const std::string& prefix,
               std::map<std::string, double>& out) {
  for (const auto& [k, v] : j.items()) {
    if (v.is_object())
      numbersOf(v, prefix + k + ".", out);
    else if (v.is_number())
      out[prefix + k] = v.get<double>();
    else if (v.is_boolean())
      out[prefix + k] = v.get<bool>() ? 1.0 : 0.0;
  }
}

TEST(EvaluationResult, ADriveEvaluationReadsBackAndWritesTheSameBytes) {
  const EvaluationResult r = readEvaluationJson(kDriveMetrics);
  ASSERT_TRUE(r.trajectory);
  EXPECT_EQ(r.loops.size(), 1u);
  ASSERT_TRUE(r.drift_by_label);
  EXPECT_TRUE(r.map && r.map_aligned);
  const fs::path copy = test::testTmp() / "metrics.json";
  writeEvaluationJson(copy, r);
  EXPECT_EQ(readFile(copy), readFile(kDriveMetrics));
}

TEST(EvaluationResult, FiguresAreTheFilesNumbersWithoutTimings) {
  std::map<std::string, double> expected;
  numbersOf(nlohmann::json::parse(readFile(kDriveMetrics)), "", expected);
  std::erase_if(expected, [](const auto& kv) {
    return kv.first.starts_with("timing_ms_per_scan.") || kv.first == "scans_per_s";
  });
  const std::map<std::string, double> figures =
      evaluationFigures(readEvaluationJson(kDriveMetrics));
  EXPECT_EQ(figures, expected);
  EXPECT_EQ(figures.at("loop_closures"), 1.0);
  EXPECT_EQ(figures.at("reliability.reliable"), 1.0);
}

// The end drift, absent from that older file, is written when measured and read back.
TEST(EvaluationResult, TheEndDriftReadsBackWhenMeasured) {
  EvaluationResult r = readEvaluationJson(kDriveMetrics);
  ASSERT_TRUE(r.trajectory);
  EXPECT_FALSE(r.trajectory->end_drift_pct);
  EXPECT_EQ(evaluationFigures(r).count("end_drift_pct"), 0u);
  r.trajectory->end_drift_pct = 0.25;
  const fs::path file = test::testTmp() / "metrics.json";
  writeEvaluationJson(file, r);
  const EvaluationResult back = readEvaluationJson(file);
  ASSERT_TRUE(back.trajectory && back.trajectory->end_drift_pct);
  EXPECT_EQ(*back.trajectory->end_drift_pct, 0.25);
  EXPECT_EQ(evaluationFigures(back).at("end_drift_pct"), 0.25);
}

TEST(EvaluationResult, WithoutGroundTruthTheTrajectoryIsSkippedInTheFile) {
  EvaluationResult r = readEvaluationJson(kDriveMetrics);
  r.trajectory.reset();
  r.map.reset();
  r.map_aligned.reset();
  const fs::path file = test::testTmp() / "metrics.json";
  writeEvaluationJson(file, r);
  const auto j = nlohmann::json::parse(readFile(file));
  EXPECT_EQ(j.at("trajectory_metrics"), "skipped: no ground truth");
  EXPECT_EQ(j.at("initial_pose"), "identity (no ground truth)");
  EXPECT_TRUE(j.at("map_mean_dist_m").is_null());
  EXPECT_FALSE(j.contains("ate_rmse_m") || j.contains("map_median_dist_m"));
  const EvaluationResult back = readEvaluationJson(file);
  EXPECT_FALSE(back.trajectory || back.map);
  EXPECT_EQ(evaluationFigures(back).count("ate_rmse_m"), 0u);
}

TEST(EvaluationResult, AFileThatIsNotAMetricsJsonIsNamed) {
  const fs::path file = test::testTmp() / "metrics.json";
  writeFileAtomic(file, "{\"scans\": 3}\n");
  try {
    readEvaluationJson(file);
    FAIL() << "read a file without the evaluation's keys";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(file.string() + ": not a metrics.json"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace slamroute::evaluate
