// End to end: `slamroute run --vehicles 2` on the plus-shaped test net (survey -> graph -> plan
// postman and a fleet of two -> drive both, the fleet in one SUMO session -> SLAM of the postman
// drive, of each vehicle and the fleet merge -> report with each vehicle's trajectory), then
// --resume keeps every step.
#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include <nlohmann/json.hpp>

#include <cmath>

#include "Chromium.hpp"
#include "CliTestUtil.hpp"
#include "HtmlFleetDrives.hpp"
#include "ReportFleet.hpp"
#include "slamroute/core/AtomicFile.hpp"
#include "slamroute/core/FleetRoute.hpp"

namespace slamroute {
namespace {
namespace fs = std::filesystem;

/// Pixels of exactly vehicle k's colour in the picture.
int pixelsOfVehicle(const cv::Mat& img, std::size_t k) {
  const auto c = cli::vehicleColour(k);
  int n = 0;
  for (int r = 0; r < img.rows; ++r)
    for (int col = 0; col < img.cols; ++col) {
      const auto& px = img.at<cv::Vec3b>(r, col);
      n += px[0] == c[0] && px[1] == c[1] && px[2] == c[2];
    }
  return n;
}

void expectFleetFiles(const fs::path& out) {
  const auto route = nlohmann::json::parse(readFile(out / "routes" / "fleet.json"));
  ASSERT_EQ(route["vehicles"].size(), 2u);
  EXPECT_DOUBLE_EQ(route["fleet"]["edge_coverage_pct"].get<double>(), 100.0);
  EXPECT_NE(readFile(out / "routes" / "fleet.rou.xml").find("mapper_1"), std::string::npos);
  for (const char* v : {"vehicle_0", "vehicle_1"}) {
    EXPECT_TRUE(fs::exists(out / "drives" / "fleet" / v / "groundtruth.tum")) << v;
    EXPECT_TRUE(fs::exists(out / "eval" / "fleet" / v / "metrics.json")) << v;
    EXPECT_TRUE(fs::exists(out / "eval" / "fleet" / ("merged_" + std::string(v) + ".tum"))) << v;
  }
  EXPECT_TRUE(fs::exists(out / "drives" / "fleet" / "fleet.json"));
  // One set of crew files per vehicle (the plus net is not on the globe: no .gpx)
  for (const char* f : {"fleet.vehicle_0_instructions.md", "fleet.vehicle_1_instructions.csv"})
    EXPECT_TRUE(fs::exists(out / "routes" / f)) << f;
  EXPECT_FALSE(fs::exists(out / "routes" / "fleet.vehicle_2_instructions.md"));
  EXPECT_TRUE(fs::exists(out / "eval" / "fleet" / "merged_map_error_top.png"));
  const auto m = nlohmann::json::parse(readFile(out / "eval" / "fleet" / "fleet_metrics.json"));
  ASSERT_EQ(m["vehicles"].size(), 2u);
  for (const char* k : {"common_ate_after_m", "completeness_pct", "map_median_dist_m",
                        "map_aligned_median_dist_m", "map_far_share", "map_accuracy_max_m"})
    EXPECT_TRUE(m[k].is_number()) << k;
}

void expectFleetReport(const fs::path& out) {
  const std::string report = readFile(out / "report.md");
  for (const char* s :
       {"## Fleet: 2 vehicles share the streets", "report/route_fleet.png", "| makespan / bound |",
        "| single postman route from the depot, L1 [km] |",
        "| this run's postman route (after the legal repair) [km] |", "| mapper_0 |",
        "| mapper_1 |", "| merged map |", "### Fleet: SLAM per vehicle and the merged map",
        "s for the single postman route", "| street facades covered by the merged map [%] |",
        "eval/fleet/merged_map_error_top.png", "| postman |"})
    EXPECT_NE(report.find(s), std::string::npos) << s << "\n" << report;
  // The route map draws each vehicle in its own colour, and no third.
  const cv::Mat img = cv::imread((out / "report" / "route_fleet.png").string(), cv::IMREAD_COLOR);
  ASSERT_FALSE(img.empty());
  EXPECT_GT(pixelsOfVehicle(img, 0), 200);
  EXPECT_GT(pixelsOfVehicle(img, 1), 200);
  EXPECT_EQ(pixelsOfVehicle(img, 2), 0);
}

/// The page's fleet trajectories: one per vehicle, and their errors are the fleet's common ATE
/// (fleet_metrics.json) under the one alignment of all vehicles. Returns "mapper_0:N0,..." with
/// each vehicle's number of trajectory points.
std::string expectFleetDrives(const fs::path& out) {
  const auto m = nlohmann::json::parse(readFile(out / "eval" / "fleet" / "fleet_metrics.json"));
  const auto drives =
      cli::fleetDriveLayers(out / "drives" / "fleet", out / "eval" / "fleet", cli::MapFrame{});
  EXPECT_EQ(drives.size(), m["vehicles"].size());
  std::string counts;
  for (std::size_t k = 0; k < drives.size(); ++k) {
    const auto& err = drives[k]["drive"]["err"];
    EXPECT_EQ(drives[k]["id"], m["vehicles"][k]["id"]);
    EXPECT_GT(err.size(), 100u);  // the plus net's short drives are not thinned
    double sq = 0.0;
    for (const auto& e : err) sq += e.get<double>() * e.get<double>();
    EXPECT_NEAR(std::sqrt(sq / static_cast<double>(err.size())),
                m["vehicles"][k]["common_ate_after_m"].get<double>(), 2e-3)
        << k;
    counts += (k ? "," : "") + drives[k]["id"].get<std::string>() + ":" +
              std::to_string(drives[k]["drive"]["gt"].size());
  }
  return counts;
}

/// report.html in Chromium: the postman route and the fleet (opened at #fleet) drawn without
/// errors, one route feature per SUMO edge of each vehicle, each vehicle's trajectory on the
/// slider, its merged map and its tables.
void expectFleetPage(const fs::path& out, const fs::path& work) {
  const std::string drive_counts = expectFleetDrives(out);
  if (!test::haveChromium()) GTEST_SKIP() << "chromium not installed (scripts/setup.sh does)";
  ASSERT_TRUE(fs::exists(out / "report.html"));
  const auto route = nlohmann::json::parse(readFile(out / "routes" / "fleet.json"));
  std::string features;
  for (std::size_t k = 0; k < route["vehicles"].size(); ++k)
    features += (k ? "," : "") + FleetRoute::vehicleId(k) + ":" +
                std::to_string(route["vehicles"][k]["sumo_edges"].size());
  const test::Browser b = test::openInChromium(out / "report.html", work, {}, "#fleet");
  EXPECT_EQ(test::bodyAttr(b.dom, "data-status"), "ok") << b.log;
  EXPECT_EQ(test::bodyAttr(b.dom, "data-errors"), "0") << test::bodyAttr(b.dom, "data-last-error");
  EXPECT_EQ(test::bodyAttr(b.dom, "data-fleet-features"), features);
  EXPECT_EQ(test::bodyAttr(b.dom, "data-fleet-drives"), drive_counts);
  // The slider's readout names every vehicle's error at the shared time, not "no evaluated drive".
  EXPECT_EQ(b.dom.find("<div id=\"readout\">no evaluated drive"), std::string::npos);
  for (const char* s :
       {"<div id=\"readout\">t ", " s   (driven, trajectory error)\nmapper_0: 0.000 km, error ",
        "\nmapper_1: 0.000 km, error "})
    EXPECT_NE(b.dom.find(s), std::string::npos) << s;
  EXPECT_EQ(b.log.find("CONSOLE"), std::string::npos) << b.log;
  for (const char* s :
       {"<option value=\"1\">fleet (2 vehicles)</option>",
        "<img id=\"fleet-map-error\" src=\"data:image/png;base64,iVBORw0KGgo",
        "<h2>Fleet: makespan</h2>", "<td>makespan / bound</td>", "<h2>Fleet: per vehicle</h2>",
        "<td>mapper_1</td>", "<td>street facades covered by the merged map [%]</td>"})
    EXPECT_NE(b.dom.find(s), std::string::npos) << s;
  // The legend names each vehicle with its colour, the fleet being the route shown.
  const auto c = cli::vehicleColour(1);
  EXPECT_NE(b.dom.find("rgb(" + std::to_string(c[2]) + ", " + std::to_string(c[1]) + ", " +
                       std::to_string(c[0]) + ")"),
            std::string::npos);
  EXPECT_NE(b.dom.find(" mapper_1: "), std::string::npos);
}

TEST(RunFleetCli, AFleetOfTwoBesideThePostmanOnThePlusNetThenResume) {
  const auto dir = test::cliTempDir("run_fleet");
  std::ofstream(dir / "fast.yaml") << "evaluate:\n  input:\n    scan_stride: 5\n";
  const std::string cmd = "--config " + (dir / "fast.yaml").string() + " run --net " +
                          std::string(SLAMROUTE_SOURCE_DIR) + "/networks/test/plus.net.xml --out " +
                          (dir / "out").string() + " --planners postman --vehicles 2";
  const auto r = test::runCli(cmd);
  ASSERT_EQ(r.code, 0) << r.out;
  const fs::path out = dir / "out";
  expectFleetFiles(out);
  expectFleetReport(out);
  expectFleetPage(out, dir);
  // survey, graph, two plans, two drives, two evaluations: all kept, the report written again.
  const std::string metrics = readFile(out / "eval" / "fleet" / "fleet_metrics.json");
  const auto again = test::runCli(cmd + " --resume");
  ASSERT_EQ(again.code, 0) << again.out;
  EXPECT_EQ(test::countOf(again.out, "  kept     "), 8) << again.out;
  EXPECT_EQ(test::countOf(again.out, "  started  "), 0) << again.out;
  EXPECT_EQ(readFile(out / "eval" / "fleet" / "fleet_metrics.json"), metrics);
  EXPECT_NE(readFile(out / "report.md").find("| evaluate fleet | kept from an earlier run |"),
            std::string::npos);
  expectFleetReport(out);
}

}  // namespace
}  // namespace slamroute
