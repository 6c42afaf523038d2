// runSurvey on the 3x3 grid: traces at 10 Hz, coverage >= 90 %, depth frames with poses.
#include <gtest/gtest.h>
#include "TestTmp.hpp"

#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "slamroute/simulate/DepthCamera.hpp"
#include "slamroute/simulate/Survey.hpp"

namespace {
namespace fs = std::filesystem;
using namespace slamroute;

std::vector<std::vector<std::string>> readCsv(const fs::path& p) {
  std::ifstream in(p);
  std::vector<std::vector<std::string>> rows;
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::stringstream ss(line);
    std::string c;
    while (std::getline(ss, c, ',')) cells.push_back(c);
    rows.push_back(cells);
  }
  return rows;
}

TEST(Survey, GridSurveyCoversTheNetWithTracesAndDepthFrames) {
  const fs::path out = slamroute::test::testTmp() / "survey_grid";
  fs::remove_all(out);
  simulate::Config cfg;
  cfg.survey.depth_spacing_m = 100.0;
  cfg.depth.width = 160;  // small frames keep the test fast
  cfg.depth.height = 120;
  simulate::SurveyOptions o;
  o.net = fs::path(SLAMROUTE_SOURCE_DIR) / "networks/test/grid3x3.net.xml";
  o.out_dir = out;
  o.seed = 3;
  const simulate::SurveyResult r = simulate::runSurvey(o, cfg);

  EXPECT_EQ(r.drivable_edges, 24u);
  EXPECT_GE(r.coverage_pct, 90.0);
  EXPECT_DOUBLE_EQ(r.planned_coverage_pct, 100.0);
  const auto j = nlohmann::json::parse(std::ifstream(out / "survey.json"));
  EXPECT_DOUBLE_EQ(j["coverage_pct"].get<double>(), r.coverage_pct);

  const auto traces = readCsv(out / "traces.csv");
  ASSERT_GT(traces.size(), 100u);
  EXPECT_EQ(traces[0],
            (std::vector<std::string>{"t", "vehicle", "x", "y", "z", "heading_deg", "speed"}));
  // 10 Hz per vehicle: consecutive rows of one vehicle are 0.1 s apart.
  std::map<std::string, double> last_t;
  std::size_t checked = 0;
  for (std::size_t i = 1; i < traces.size(); ++i) {
    ASSERT_EQ(traces[i].size(), 7u) << "row " << i;
    const double t = std::stod(traces[i][0]);
    auto it = last_t.find(traces[i][1]);
    if (it != last_t.end()) {
      EXPECT_NEAR(t - it->second, 0.1, 1e-6) << traces[i][1];
      ++checked;
    }
    last_t[traces[i][1]] = t;
  }
  EXPECT_GT(checked, 100u);

  const auto index = readCsv(out / "depth/index.csv");
  ASSERT_GT(index.size(), 5u);
  EXPECT_EQ(index[0].back(), "file");
  // The camera's size, so that build-graph can tell a frame of another size (width, height).
  EXPECT_EQ(index[0][10], "width");
  EXPECT_EQ(index[1][10], "160");
  EXPECT_EQ(index[1][11], "120");
  EXPECT_EQ(index.size() - 1, r.depth_frames);
  const auto img = simulate::readDepthPng(out / "depth" / index[1].back());
  EXPECT_EQ(img.width, 160);
  EXPECT_EQ(img.height, 120);
  // Nothing half-written beside the result.
  for (const auto& e : fs::directory_iterator(out.parent_path()))
    EXPECT_EQ(e.path().filename().string().find(".survey_grid.tmp"), std::string::npos);
}

}  // namespace

namespace {

TEST(Survey, DefaultCitySurveyVisitsAtLeast90PercentOfDrivableEdges) {
  const fs::path out = slamroute::test::testTmp() / "survey_city";
  fs::remove_all(out);
  simulate::Config cfg;
  cfg.survey.depth_spacing_m = 150.0;  // the default (50 m) renders ~400 frames: 20 s
  cfg.depth.width = 80;
  cfg.depth.height = 60;
  simulate::SurveyOptions o;
  o.net = fs::path(SLAMROUTE_SOURCE_DIR) / "networks/default_city/default_city.net.xml";
  o.out_dir = out;
  o.seed = 42;
  const simulate::SurveyResult r = simulate::runSurvey(o, cfg);
  EXPECT_EQ(r.drivable_edges, 71u);
  EXPECT_GE(r.coverage_pct, 90.0) << r.visited_edges << "/" << r.drivable_edges;
  EXPECT_GT(r.depth_frames, 50u);
  EXPECT_GT(r.trace_rows, 10000u);
  EXPECT_LT(r.bytes_written, 300u * 1000u * 1000u);
}

}  // namespace
