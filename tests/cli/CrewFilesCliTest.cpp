// `slamroute plan --net` writes the crew's files beside the route: GPX / KML on a geo-referenced
// net (or with --geo-origin), turn-by-turn always, and a one-line note otherwise.
#include <gtest/gtest.h>

#include <iterator>

#include "CliTestUtil.hpp"
#include "export/TestNets.hpp"

namespace slamroute::test {
namespace {
namespace fs = std::filesystem;

std::string readText(const fs::path& p) {
  std::ifstream in(p);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

const std::string kPlus = std::string(SLAMROUTE_SOURCE_DIR) + "/networks/test/plus.net.xml";

TEST(CrewFilesCli, PlanOnASyntheticNetNotesTheMissingGeoReference) {
  const fs::path dir = cliTempDir("synthetic");
  const auto r =
      runCli("plan --net " + kPlus + " --planner postman --out " + (dir / "r.json").string());
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("no geo-reference"), std::string::npos) << r.out;
  EXPECT_EQ(countLines(r.out.substr(r.out.find("note:"))), 1);
  EXPECT_FALSE(fs::exists(dir / "r.gpx"));
  EXPECT_TRUE(fs::exists(dir / "r_instructions.md"));
  EXPECT_TRUE(fs::exists(dir / "r_instructions.csv"));
  const auto placed =
      runCli("plan --net " + kPlus + " --planner postman --geo-origin 52.52,13.405 --out " +
             (dir / "p.json").string());
  ASSERT_EQ(placed.code, 0) << placed.out;
  EXPECT_TRUE(fs::exists(dir / "p.gpx"));
  EXPECT_TRUE(fs::exists(dir / "p.kml"));
}

TEST(CrewFilesCli, BadGeoOriginIsAOneLineErrorBeforeAnythingIsWritten) {
  const fs::path dir = cliTempDir("bad_origin");
  const auto r = runCli("plan --net " + kPlus + " --planner postman --geo-origin 95,13 --out " +
                        (dir / "r.json").string());
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.out.find("--geo-origin"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(dir / "r.json"));
}

TEST(CrewFilesCli, PlanOnAGeoReferencedNetWritesGpxAndKml) {
  const fs::path dir = cliTempDir("geo");
  const fs::path net = geoPlusNet(dir);  // netconvert from lon/lat nodes: a UTM projParameter
  const auto r = runCli("plan --net " + net.string() + " --planner postman --out " +
                        (dir / "plus.json").string());
  ASSERT_EQ(r.code, 0) << r.out;
  for (const char* f : {"plus.gpx", "plus.kml", "plus_instructions.md", "plus_instructions.csv"})
    EXPECT_TRUE(fs::exists(dir / f)) << f;
  EXPECT_EQ(r.out.find("no geo-reference"), std::string::npos) << r.out;
  // Every track point lies on the plus: within its junctions' lon/lat box (+- 20 m).
  std::ifstream in(dir / "plus.gpx");
  std::string line;
  int points = 0;
  while (std::getline(in, line)) {
    const auto at = line.find("<trkpt lat=\"");
    if (at == std::string::npos) continue;
    double lat = 0, lon = 0;
    ASSERT_EQ(std::sscanf(line.c_str() + at, "<trkpt lat=\"%lf\" lon=\"%lf\"", &lat, &lon), 2)
        << line;
    EXPECT_TRUE(lat > 52.4983 && lat < 52.5017 && lon > 13.3972 && lon < 13.4028) << line;
    ++points;
  }
  EXPECT_GT(points, 8);
  const std::string md = readText(dir / "plus_instructions.md");
  EXPECT_NE(md.find(" Street |"), std::string::npos) << md;
}

}  // namespace
}  // namespace slamroute::test
