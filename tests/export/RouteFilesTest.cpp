// The crew's route files: GPX valid against the GPX 1.1 schema (xmllint), KML well-formed, both
// holding the driven polyline and a point per instruction; the instruction tables.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>

#include "TestNets.hpp"
#include "TestTmp.hpp"
#include "slamroute/core/Route.hpp"
#include "slamroute/export/ExportRoute.hpp"
#include "slamroute/export/RouteFiles.hpp"

namespace slamroute::exports {
namespace {
namespace fs = std::filesystem;

const std::string kSchema = std::string(SLAMROUTE_SOURCE_DIR) + "/export/schema/gpx.xsd";

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// xmllint's exit code validating `file` against the GPX schema (0: valid).
int xmllintGpx(const fs::path& file) {
  const std::string cmd = "xmllint --noout --schema " + kSchema + " " + file.string() + " > " +
                          file.string() + ".xmllint 2>&1";
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (auto p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
  return n;
}

Route plusRoute() {
  Route r;
  r.planner = "manual";
  r.sumo_edges = {"S_C", "C_E", "E_C", "C_N", "N_C", "C_S", "S_C", "C_W"};
  return r;
}

class RouteFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    if (std::system("xmllint --version > /dev/null 2>&1") != 0)
      GTEST_SKIP() << "xmllint missing: install libxml2-utils (scripts/setup.sh does)";
  }
};

TEST_F(RouteFiles, GpxOfAGeoNetIsValidGpx11WithTrackAndTurnPoints) {
  const fs::path dir = test::testTmp();
  const SumoNet net = SumoNet::read(test::geoPlusNet(dir));
  const Route route = plusRoute();
  const auto res = exportRoute(net, route, dir / "plus.json", {});
  EXPECT_TRUE(res.note.empty()) << res.note;
  ASSERT_TRUE(fs::exists(dir / "plus.gpx"));
  ASSERT_TRUE(fs::exists(dir / "plus.kml"));
  EXPECT_EQ(xmllintGpx(dir / "plus.gpx"), 0) << slurp(dir / "plus.gpx.xmllint");
  const std::string gpx = slurp(dir / "plus.gpx");
  EXPECT_EQ(count(gpx, "<rtept "), 8);  // one per instruction (see InstructionsTest)
  const DrivenPath path = drivenPath(net, route.sumo_edges);
  EXPECT_EQ(count(gpx, "<trkpt "), static_cast<int>(path.points.size()));
  EXPECT_GT(path.points.size(), 8u);
  EXPECT_NE(gpx.find("<name>2. Turn right onto East Street</name>"), std::string::npos);
  // Every point lies in the box of the plus's junctions (+- 20 m).
  const std::regex pt("lat=\"([-0-9.]+)\" lon=\"([-0-9.]+)\"");
  int points = 0;
  for (auto it = std::sregex_iterator(gpx.begin(), gpx.end(), pt); it != std::sregex_iterator();
       ++it) {
    const double lat = std::stod((*it)[1]), lon = std::stod((*it)[2]);
    EXPECT_TRUE(lat > 52.4983 && lat < 52.5017 && lon > 13.3972 && lon < 13.4028)
        << lat << "," << lon;
    ++points;
  }
  EXPECT_EQ(points, 8 + static_cast<int>(path.points.size()));
  const std::string kml = slurp(dir / "plus.kml");
  EXPECT_EQ(std::system(("xmllint --noout " + (dir / "plus.kml").string()).c_str()), 0);
  EXPECT_EQ(count(kml, "<Placemark>"), 1 + 8);
}

TEST_F(RouteFiles, TheSchemaRejectsWhatGpx11Forbids) {
  // The validation above means something only if this schema rejects invalid GPX.
  const fs::path dir = test::testTmp();
  const SumoNet net = SumoNet::read(test::geoPlusNet(dir));
  exportRoute(net, plusRoute(), dir / "plus.json", {});
  const std::string gpx = slurp(dir / "plus.gpx");
  const auto broken = [&](const std::string& name, std::string text) {
    test::writeFile(dir / name, text);
    return xmllintGpx(dir / name);
  };
  std::string lat_out = gpx;
  lat_out.replace(lat_out.find("lat=\"") + 5, 2, "95");  // latitude 95 degrees
  EXPECT_NE(broken("lat95.gpx", lat_out), 0);
  std::string order = gpx;  // <trk> before <rte>
  const auto rte = order.find("  <rte>"), trk = order.find("  <trk>"), end = order.find("</gpx>");
  order = order.substr(0, rte) + order.substr(trk, end - trk) + order.substr(rte, trk - rte) +
          "</gpx>\n";
  EXPECT_NE(broken("order.gpx", order), 0);
  std::string version = gpx;
  version.replace(version.find("version=\"1.1\""), 13, "version=\"1.0\"");
  EXPECT_NE(broken("version.gpx", version), 0);
}

TEST_F(RouteFiles, NetWithoutGeoReferenceGetsANoteAndNoGpxUnlessPlaced) {
  const fs::path dir = test::testTmp();
  const SumoNet net =
      SumoNet::read(std::string(SLAMROUTE_SOURCE_DIR) + "/networks/test/plus.net.xml");
  const Route route = plusRoute();
  const auto res = exportRoute(net, route, dir / "a.json", {});
  EXPECT_NE(res.note.find("no geo-reference"), std::string::npos) << res.note;
  EXPECT_FALSE(fs::exists(dir / "a.gpx"));
  EXPECT_TRUE(fs::exists(dir / "a_instructions.md"));
  EXPECT_TRUE(fs::exists(dir / "a_instructions.csv"));
  RouteExportOptions placed;
  placed.geo_origin = GeoOrigin{48.1372, 11.5756};
  const auto res2 = exportRoute(net, route, dir / "b.json", placed);
  EXPECT_TRUE(res2.note.empty());
  ASSERT_TRUE(fs::exists(dir / "b.gpx"));
  EXPECT_EQ(xmllintGpx(dir / "b.gpx"), 0) << slurp(dir / "b.gpx.xmllint");
  EXPECT_NE(slurp(dir / "b.gpx").find("lat=\"48.13"), std::string::npos);
}

TEST_F(RouteFiles, InstructionTablesListEveryStep) {
  const fs::path dir = test::testTmp();
  const SumoNet net = SumoNet::read(test::geoPlusNet(dir));
  exportRoute(net, plusRoute(), dir / "plus.json", {});
  const std::string csv = slurp(dir / "plus_instructions.csv");
  std::istringstream lines(csv);
  std::string header, row;
  std::getline(lines, header);
  EXPECT_EQ(header.substr(0, 28), "step,at_m,manoeuvre,roundabo");
  std::vector<std::string> rows;
  while (std::getline(lines, row)) rows.push_back(row);
  ASSERT_EQ(rows.size(), 8u);
  EXPECT_NE(rows[1].find(",right,0,East Street,"), std::string::npos) << rows[1];
  EXPECT_NE(rows[5].find(",straight,0,South Street,"), std::string::npos) << rows[5];
  EXPECT_NE(rows[5].find(",1,loop-closure revisit,"), std::string::npos) << rows[5];
  EXPECT_NE(rows[7].find(",left,0,West Street,"), std::string::npos) << rows[7];
  const std::string md = slurp(dir / "plus_instructions.md");
  EXPECT_NE(md.find("| 8 |"), std::string::npos);
  EXPECT_NE(md.find("Turn left onto West Street"), std::string::npos);
  EXPECT_NE(md.find("coverage connection"), std::string::npos);
}

}  // namespace
}  // namespace slamroute::exports
