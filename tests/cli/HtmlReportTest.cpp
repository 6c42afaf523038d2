// report.html in a real headless browser (Debian's chromium): a one-planner `run` on the plus
// net, placed on the globe with --geo-origin, then the same run's page drawn in the net's own
// metres. The page must load offline without errors and draw one route feature per SUMO edge.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <nlohmann/json.hpp>

#include "Chromium.hpp"
#include "CliTestUtil.hpp"
#include "HtmlReport.hpp"
#include "slamroute/core/AtomicFile.hpp"
#include "slamroute/evaluate/Metrics.hpp"

namespace slamroute::test {
namespace {
namespace fs = std::filesystem;

void expectPageDrawn(const Browser& b, const std::string& route_features, std::size_t streets) {
  EXPECT_EQ(bodyAttr(b.dom, "data-status"), "ok") << b.log;
  EXPECT_EQ(bodyAttr(b.dom, "data-errors"), "0") << bodyAttr(b.dom, "data-last-error");
  EXPECT_EQ(bodyAttr(b.dom, "data-route-features"), route_features);
  EXPECT_EQ(bodyAttr(b.dom, "data-streets"), std::to_string(streets));
  EXPECT_NE(b.dom.find("<title>slamroute report: plus.net.xml (ready)</title>"), std::string::npos);
  // Console messages (page errors, failed loads) show in the log as "CONSOLE(line)".
  EXPECT_EQ(b.log.find("CONSOLE"), std::string::npos) << b.log;
  EXPECT_EQ(b.log.find("Uncaught"), std::string::npos) << b.log;
  EXPECT_NE(b.dom.find("<th>ATE RMSE [m]</th>"), std::string::npos);
  EXPECT_NE(b.dom.find("leaflet-container"), std::string::npos);
  EXPECT_NE(b.dom.find("<img id=\"map-error\" src=\"data:image/png;base64,iVBORw0KGgo"),
            std::string::npos);
}

/// The page's drift layer colours each street by its drift along the street and names the end
/// to end figure beside it, both as the evaluation's per_edge.csv gives them.
void expectDriftAlongTheStreet(const std::string& html, const fs::path& per_edge_csv) {
  const std::string open = "id=\"report-data\">";
  const std::size_t from = html.find(open) + open.size();
  const auto data = nlohmann::json::parse(html.substr(from, html.find("</script>", from) - from));
  const auto& drift = data["planners"][0]["drift"];
  std::size_t checked = 0, differ = 0;
  for (const auto& row : evaluate::readPerEdgeCsv(per_edge_csv)) {
    if (!std::isfinite(row.drift_pct)) continue;
    const auto it = std::find_if(drift.begin(), drift.end(),
                                 [&](const auto& d) { return d["edge"] == row.edge; });
    ASSERT_NE(it, drift.end()) << row.edge;
    EXPECT_NEAR((*it)["pct"].get<double>(), row.window_drift_pct, 6e-4) << row.edge;
    EXPECT_NEAR((*it)["end"].get<double>(), row.drift_pct, 6e-4) << row.edge;
    ++checked;
    differ += std::abs(row.window_drift_pct - row.drift_pct) > 0.01;
  }
  EXPECT_EQ(checked, drift.size());
  EXPECT_GT(differ, 0u);  // else the test could not tell the two figures apart
}

TEST(HtmlReport, RunWritesAPageThatChromiumDrawsOffline) {
  if (!haveChromium()) GTEST_SKIP() << "chromium not installed (scripts/setup.sh installs it)";
  const fs::path dir = cliTempDir("html");
  std::ofstream(dir / "fast.yaml") << "evaluate:\n  input:\n    scan_stride: 5\n";
  const std::string net = std::string(SLAMROUTE_SOURCE_DIR) + "/networks/test/plus.net.xml";
  const auto r =
      runCli("--config " + (dir / "fast.yaml").string() + " run --net " + net + " --out " +
             (dir / "out").string() + " --planners postman --geo-origin 52.52,13.405");
  ASSERT_EQ(r.code, 0) << r.out;
  const fs::path page = dir / "out" / "report.html";
  ASSERT_TRUE(fs::exists(page)) << r.out;
  const std::string html = readFile(page);
  // Self-contained: no script, style or image comes from elsewhere.
  for (const char* ref : {"<script src", "<link ", "url(http", "src=\"http"})
    EXPECT_EQ(html.find(ref), std::string::npos) << ref;
  const auto route = nlohmann::json::parse(readFile(dir / "out" / "routes" / "postman.json"));
  const std::size_t edges = route["sumo_edges"].size();
  ASSERT_GT(edges, 4u);
  const std::string features = "postman:" + std::to_string(edges);
  // The plus has 8 passenger edges; the page is on the globe (WGS84).
  EXPECT_NE(html.find("\"geo\":true"), std::string::npos);
  expectDriftAlongTheStreet(html, dir / "out" / "eval" / "postman" / "per_edge.csv");
  const Browser geo = openInChromium(page, dir, dir / "report.png");
  expectPageDrawn(geo, features, 8);
  ASSERT_TRUE(fs::exists(dir / "report.png"));
  EXPECT_GT(fs::file_size(dir / "report.png"), 20000u);
  EXPECT_EQ(readFile(dir / "report.png").substr(1, 3), "PNG");

  // The same run drawn in the net's own metres (Leaflet's plain CRS), as without --geo-origin.
  cli::ReportInputs in;
  in.net = net;
  in.out = dir / "out";
  in.graph_json = dir / "out" / "graph" / "graph.json";
  in.planners = {"postman"};
  ASSERT_EQ(cli::writeHtmlReport(in, ""), "");
  EXPECT_NE(readFile(page).find("\"geo\":false"), std::string::npos);
  fs::remove_all(dir / "profile");
  expectPageDrawn(openInChromium(page, dir), features, 8);
}

}  // namespace
}  // namespace slamroute::test
