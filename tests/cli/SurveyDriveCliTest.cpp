// `slamroute drive` / `slamroute survey` from the command line: a good drive, and bad input
// (missing edge, forbidden turn, empty route, unknown net; evaluate with a bad odometry.yaml)
// giving a one-line error naming the file, a non-zero exit and nothing written.
#include <gtest/gtest.h>

#include <unistd.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "CliTestUtil.hpp"
#include "slamroute/core/AtomicFile.hpp"
#include "slamroute/core/OdometrySpec.hpp"

namespace slamroute {
namespace {
namespace fs = std::filesystem;

const std::string kGrid = std::string(SLAMROUTE_SOURCE_DIR) + "/networks/test/grid3x3.net.xml";

fs::path writeRoute(const fs::path& dir, const std::string& name, const std::string& json) {
  const fs::path p = dir / name;
  std::ofstream(p) << json;
  return p;
}

/// Drives two streets of the 3x3 grid into DIR/drive (no mesh); false when the drive fails.
bool shortDrive(const fs::path& dir) {
  const auto route = writeRoute(dir, "route.json", R"(["g00_g01","g01_g11"])");
  const auto d = test::runCli("drive --net " + kGrid + " --route " + route.string() + " --out " +
                              (dir / "drive").string() + " --no-mesh --log-level warn");
  EXPECT_EQ(d.code, 0) << d.out;
  return d.code == 0;
}

TEST(SurveyDriveCli, DriveWritesTheDriveFolder) {
  const auto dir = test::cliTempDir("drive_ok");
  const auto route = writeRoute(dir, "route.json", R"(["g00_g01","g01_g11","g11_g21"])");
  const auto r = test::runCli("--seed 9 drive --net " + kGrid + " --route " + route.string() +
                              " --out " + (dir / "out").string() + " --no-mesh --log-level warn");
  ASSERT_EQ(r.code, 0) << r.out;
  for (const char* f : {"groundtruth.tum", "pose_edges.csv", "sensor.yaml", "world.yaml",
                        "traffic.csv", "drive.json", "odometry.csv", "odometry.yaml"})
    EXPECT_TRUE(fs::exists(dir / "out" / f)) << f;
  // odometry.yaml states the simulated odometry's noise (DriveConfig defaults).
  const auto spec = readOdometrySpec(dir / "out/odometry.yaml");
  ASSERT_TRUE(spec.has_value());
  EXPECT_DOUBLE_EQ(spec->gyro_noise_deg_s, 0.1);
  EXPECT_DOUBLE_EQ(spec->gyro_bias_sigma_deg_s, 0.05);
  EXPECT_DOUBLE_EQ(spec->scale_sigma, 0.01);
  const auto j = nlohmann::json::parse(std::ifstream(dir / "out/drive.json"));
  EXPECT_EQ(j["teleports"], 0);
  EXPECT_EQ(j["seed"], 9);
  EXPECT_EQ(j["route"], nlohmann::json({"g00_g01", "g01_g11", "g11_g21"}));
}

TEST(SurveyDriveCli, EvaluateRejectsABadOdometrySpecAndWritesNothing) {
  const auto dir = test::cliTempDir("evaluate_bad_spec");
  ASSERT_TRUE(shortDrive(dir));
  std::ofstream(dir / "drive/odometry.yaml") << "gyro_noise_deg_s: -0.1\n";
  const auto r = test::runCli("--log-level warn evaluate --drive " + (dir / "drive").string() +
                              " --out " + (dir / "eval").string());
  EXPECT_NE(r.code, 0) << r.out;
  EXPECT_EQ(test::countLines(r.out), 1) << r.out;
  EXPECT_NE(r.out.find("odometry.yaml: 'gyro_noise_deg_s' must be a number >= 0"),
            std::string::npos)
      << r.out;
  EXPECT_FALSE(fs::exists(dir / "eval"));
}

TEST(SurveyDriveCli, EvaluateRejectsABadMapTileSizeAtOnce) {
  const auto dir = test::cliTempDir("evaluate_bad_tile");
  const fs::path cfg = dir / "tile.yaml";
  std::ofstream(cfg) << "evaluate:\n  output:\n    map_tile_m: 0\n";
  // The drive need not exist: the config is checked before anything is read.
  test::expectCleanFailure("--config " + cfg.string() + " evaluate --drive " +
                               (dir / "drive").string() + " --out " + (dir / "eval").string(),
                           cfg.string() + ": evaluate.output.map_tile_m must be >= 10 (got 0)", dir,
                           1);
}

TEST(SurveyDriveCli, AFailedEvaluateLeavesNoHalfOutput) {
  // A bad pose_edges.csv fails the evaluation (the drive checks find it before the SLAM; a
  // failure after it unwinds the same staging folder, OutputSwapTest): no output folder is left,
  // an earlier evaluation in the same folder stays whole, and a folder that holds something else
  // is never written into.
  const auto dir = test::cliTempDir("evaluate_late_failure");
  ASSERT_TRUE(shortDrive(dir));
  auto evaluate = [&](const std::string& out) {
    return test::runCli("--log-level warn evaluate --scan-stride 10 --drive " +
                        (dir / "drive").string() + " --out " + (dir / out).string());
  };
  const std::string pose_edges = readFile(dir / "drive/pose_edges.csv");
  const auto good = evaluate("eval");
  ASSERT_EQ(good.code, 0) << good.out;
  const std::string estimate = readFile(dir / "eval" / "estimate.tum");
  const std::string metrics = readFile(dir / "eval" / "metrics.json");
  std::ofstream(dir / "drive/pose_edges.csv") << "t,edge\nnot a time,g00_g01\n";
  const auto r = evaluate("fresh");
  EXPECT_NE(r.code, 0) << r.out;
  EXPECT_EQ(test::countLines(r.out), 1) << r.out;
  EXPECT_NE(r.out.find("pose_edges.csv"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(dir / "fresh"));
  EXPECT_NE(evaluate("eval").code, 0);
  EXPECT_EQ(readFile(dir / "eval" / "estimate.tum"), estimate);
  EXPECT_EQ(readFile(dir / "eval" / "metrics.json"), metrics);
  for (const auto& e : fs::directory_iterator(dir))  // no staging folder left
    EXPECT_EQ(e.path().filename().string().find(".tmp."), std::string::npos) << e.path();
  fs::create_directories(dir / "foreign");
  std::ofstream(dir / "foreign" / "notes.txt") << "keep me";
  std::ofstream(dir / "drive/pose_edges.csv") << pose_edges;  // the drive is fine again
  const auto f = evaluate("foreign");
  EXPECT_NE(f.code, 0) << f.out;
  EXPECT_NE(f.out.find("refusing to overwrite"), std::string::npos) << f.out;
  EXPECT_EQ(readFile(dir / "foreign" / "notes.txt"), "keep me");
}

TEST(SurveyDriveCli, DriveRejectsAnEdgeMissingFromTheNet) {
  const auto dir = test::cliTempDir("drive_missing_edge");
  const auto route = writeRoute(dir, "route.json", R"(["g00_g01","g01_gXX"])");
  test::expectCleanFailure(
      "drive --net " + kGrid + " --route " + route.string() + " --out " + (dir / "out").string(),
      "route.json: edge 'g01_gXX'", dir, 1);
}

TEST(SurveyDriveCli, DriveWithStrictTurnsRejectsATurnSumoDoesNotAllow) {
  const auto dir = test::cliTempDir("drive_bad_turn");
  const auto route = writeRoute(dir, "route.json", R"({"sumo_edges":["g00_g01","g10_g11"]})");
  test::expectCleanFailure("drive --strict-turns --net " + kGrid + " --route " + route.string() +
                               " --out " + (dir / "out").string(),
                           "'g00_g01' -> 'g10_g11'", dir, 1);
}

TEST(SurveyDriveCli, DriveJoinsATurnSumoDoesNotAllowWithAWarning) {
  const auto dir = test::cliTempDir("drive_joined_turn");
  const auto route = writeRoute(dir, "route.json", R"({"sumo_edges":["g00_g01","g10_g11"]})");
  const auto r = test::runCli("drive --net " + kGrid + " --route " + route.string() + " --out " +
                              (dir / "out").string() + " --no-mesh --log-level warn");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("1 turn(s) SUMO does not allow joined by the shortest legal detour"),
            std::string::npos)
      << r.out;
  const auto j = nlohmann::json::parse(std::ifstream(dir / "out/drive.json"));
  const auto edges = j["route"].get<std::vector<std::string>>();
  ASSERT_GT(edges.size(), 2u);
  EXPECT_EQ(edges.front(), "g00_g01");
  EXPECT_EQ(edges.back(), "g10_g11");
}

TEST(SurveyDriveCli, DriveRejectsAnEmptyRoute) {
  const auto dir = test::cliTempDir("drive_empty");
  const auto route = writeRoute(dir, "route.json", "[]");
  test::expectCleanFailure(
      "drive --net " + kGrid + " --route " + route.string() + " --out " + (dir / "out").string(),
      "route.json", dir, 1);
}

TEST(SurveyDriveCli, DriveAndSurveyRejectAnUnknownNet) {
  const auto dir = test::cliTempDir("unknown_net");
  const auto route = writeRoute(dir, "route.json", R"(["g00_g01"])");
  test::expectCleanFailure("drive --net " + (dir / "nowhere.net.xml").string() + " --route " +
                               route.string() + " --out " + (dir / "out").string(),
                           "nowhere.net.xml", dir, 1);
  test::expectCleanFailure(
      "survey --net " + (dir / "nowhere.net.xml").string() + " --out " + (dir / "out").string(),
      "nowhere.net.xml", dir, 1);
}

TEST(SurveyDriveCli, DriveRemovesTheStagingFolderOfAKilledDrive) {
  // A drive killed by a signal leaves its hidden .out.tmp.PID folder; the next drive to the same
  // folder removes it once that process is gone, and leaves a live process's one alone.
  const auto dir = test::cliTempDir("drive_stale");
  long pid_max = 4194304;
  std::ifstream("/proc/sys/kernel/pid_max") >> pid_max;
  const fs::path dead = dir / (".out.tmp." + std::to_string(pid_max + 1));  // no such process
  const fs::path live = dir / (".out.tmp." + std::to_string(::getpid()));   // this test
  fs::create_directories(dead);
  fs::create_directories(live);
  std::ofstream(dead / "groundtruth.tum") << "0 0 0 0 0 0 0 1\n";
  const auto route = writeRoute(dir, "route.json", R"(["g00_g01"])");
  const auto r = test::runCli("drive --net " + kGrid + " --route " + route.string() + " --out " +
                              (dir / "out").string() + " --no-mesh --log-level warn");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_FALSE(fs::exists(dead));
  EXPECT_TRUE(fs::exists(live));
  EXPECT_TRUE(fs::exists(dir / "out" / "drive.json"));
}

TEST(SurveyDriveCli, DriveRefusesToOverwriteAForeignFolder) {
  const auto dir = test::cliTempDir("drive_foreign");
  fs::create_directories(dir / "out");
  std::ofstream(dir / "out" / "precious.txt") << "keep me";
  const auto route = writeRoute(dir, "route.json", R"(["g00_g01"])");
  const auto r = test::runCli("drive --net " + kGrid + " --route " + route.string() + " --out " +
                              (dir / "out").string());
  EXPECT_NE(r.code, 0) << r.out;
  EXPECT_TRUE(fs::exists(dir / "out" / "precious.txt"));
}

}  // namespace
}  // namespace slamroute
