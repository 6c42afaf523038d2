// report.md's aco-ga against postman section (cli/ReportCoverage.cpp) from a run folder's files.
#include <gtest/gtest.h>

#include <fstream>

#include "CliTestUtil.hpp"
#include "ReportSections.hpp"
#include "slamroute/core/SumoNet.hpp"

namespace slamroute::cli {
namespace {

void writeJson(const std::filesystem::path& p, const nlohmann::json& j) {
  std::filesystem::create_directories(p.parent_path());
  std::ofstream(p) << j.dump();
}

TEST(ReportCoverage, RatiosToPostmanFromTheRunFiles) {
  const auto dir = test::cliTempDir("report_coverage");
  const auto net = std::string(SLAMROUTE_SOURCE_DIR) + "/networks/test/plus.net.xml";
  RoadGraph::fromSumoNet(SumoNet::read(net)).writeJson(dir / "graph.json");
  writeJson(dir / "routes/postman.json", {{"sumo_length", {{"total_m", 2000.0}}}});
  writeJson(dir / "routes/aco-ga.json", {{"sumo_length", {{"total_m", 2300.0}}}});
  writeJson(dir / "eval/postman/metrics.json",
            {{"ate_rmse_m", 0.5}, {"directed_coverage", {{"edges_pct", 97.24}}}});
  writeJson(dir / "eval/aco-ga/metrics.json",
            {{"ate_rmse_m", 0.35}, {"directed_coverage", {{"edges_pct", 100.0}}}});
  ReportInputs in;
  in.out = dir;
  in.graph_json = dir / "graph.json";
  in.planners = {"postman", "aco-ga"};
  const ReportData data(in);
  std::ostringstream md;
  writeCoverageVsPostmanSection(md, data);
  EXPECT_NE(md.str().find("| 1.150 | 0.700 | 100.0 / 97.2 |"), std::string::npos) << md.str();
  // Without postman among the planners there is nothing to compare with.
  in.planners = {"aco-ga"};
  std::ostringstream none;
  writeCoverageVsPostmanSection(none, ReportData(in));
  EXPECT_EQ(none.str(), "");
}

}  // namespace
}  // namespace slamroute::cli
