// `slamroute plan --net` writes the crew's files beside the route: GPX / KML on a geo-referenced
// net (or with --geo-origin), turn-by-turn always, and a one-line note otherwise.
#include <gtest/gtest.h>

#include <iterator>
#include <nlohmann/json.hpp>
#include <set>

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

/// The plus's arm ends (N, E, S, W) within 25 m of one of the GPX file's track points.
std::set<char> armsOnTrack(const fs::path& gpx) {
  std::set<char> arms;
  std::ifstream in(gpx);
  for (std::string line; std::getline(in, line);) {
    double lat = 0, lon = 0;
    const auto at = line.find("<trkpt lat=\"");
    if (at == std::string::npos ||
        std::sscanf(line.c_str() + at, "<trkpt lat=\"%lf\" lon=\"%lf\"", &lat, &lon) != 2)
      continue;
    for (const auto& g : kGeoPlus) {
      const double north_m = (lat - g.lat) * 111320.0, east_m = (lon - g.lon) * 67800.0;
      if (g.id[0] != 'C' && north_m * north_m + east_m * east_m < 25.0 * 25.0) arms.insert(g.id[0]);
    }
  }
  return arms;
}

/// The arms whose streets (C_N, N_C, ...) the route's SUMO edges drive.
std::set<char> armsOfRoute(const nlohmann::json& route) {
  std::set<char> arms;
  for (const auto& e : route["sumo_edges"]) {
    const std::string id = e.get<std::string>();
    arms.insert(id[0] == 'C' ? id[2] : id[0]);
  }
  return arms;
}

std::string planFleet(const fs::path& net, const fs::path& out, int vehicles) {
  return "plan --net " + net.string() + " --planner partition --vehicles " +
         std::to_string(vehicles) + " --out " + out.string();
}

const char* const kCrewSuffixes[] = {".gpx", ".kml", "_instructions.md", "_instructions.csv"};

TEST(CrewFilesCli, AFleetGetsOneGpxPerVehicleWhoseTrackDrivesThatVehiclesStreets) {
  const fs::path dir = cliTempDir("fleet_geo");
  const fs::path net = geoPlusNet(dir);
  const auto r = runCli(planFleet(net, dir / "f.json", 2));
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_EQ(r.out.find("no geo-reference"), std::string::npos) << r.out;
  const auto fleet = nlohmann::json::parse(readText(dir / "f.json"));
  ASSERT_EQ(fleet["vehicles"].size(), 2u);
  std::set<char> all;
  for (int k = 0; k < 2; ++k) {
    const std::string stem = "f.vehicle_" + std::to_string(k);
    for (const char* suffix : kCrewSuffixes)
      EXPECT_TRUE(fs::exists(dir / (stem + suffix))) << suffix;
    // The track goes out to exactly the arms this vehicle's route drives, and no other.
    const std::set<char> arms = armsOfRoute(fleet["vehicles"][k]);
    EXPECT_EQ(armsOnTrack(dir / (stem + ".gpx")), arms) << stem;
    EXPECT_NE(
        readText(dir / (stem + ".gpx")).find("vehicle " + std::to_string(k) + " of 2 (mapper_"),
        std::string::npos);
    all.insert(arms.begin(), arms.end());
  }
  EXPECT_EQ(all, (std::set<char>{'E', 'N', 'S', 'W'}));
  EXPECT_FALSE(fs::exists(dir / "f.vehicle_2.gpx"));
  EXPECT_FALSE(fs::exists(dir / "f.gpx"));  // one file per vehicle, none for the fleet as a whole
}

TEST(CrewFilesCli, AFleetReplacedByFewerVehiclesOrOneRouteLeavesNoOlderVehicleFiles) {
  const fs::path dir = cliTempDir("fleet_replace");
  const fs::path net = geoPlusNet(dir);
  ASSERT_EQ(runCli(planFleet(net, dir / "f.json", 3)).code, 0);
  for (const char* suffix : kCrewSuffixes)
    ASSERT_TRUE(fs::exists(dir / ("f.vehicle_2" + std::string(suffix))));
  std::ofstream(dir / "f.vehicle_2.notes.txt") << "the crew's own notes";  // not ours: kept
  ASSERT_EQ(runCli(planFleet(net, dir / "f.json", 2)).code, 0);
  for (const char* suffix : kCrewSuffixes) {
    EXPECT_TRUE(fs::exists(dir / ("f.vehicle_1" + std::string(suffix)))) << suffix;
    EXPECT_FALSE(fs::exists(dir / ("f.vehicle_2" + std::string(suffix)))) << suffix;
  }
  EXPECT_TRUE(fs::exists(dir / "f.vehicle_2.notes.txt"));
  const auto single = runCli("plan --net " + net.string() + " --planner postman --out " +
                             (dir / "f.json").string());
  ASSERT_EQ(single.code, 0) << single.out;
  EXPECT_TRUE(fs::exists(dir / "f.gpx"));
  for (int k = 0; k < 2; ++k)
    for (const char* suffix : kCrewSuffixes)
      EXPECT_FALSE(fs::exists(dir / ("f.vehicle_" + std::to_string(k) + suffix))) << k << suffix;
}

TEST(CrewFilesCli, AFleetOnASyntheticNetGetsInstructionsAndTheNoteOnce) {
  const fs::path dir = cliTempDir("fleet_synthetic");
  const auto r = runCli(planFleet(kPlus, dir / "f.json", 2));
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_EQ(countOf(r.out, "no geo-reference"), 1) << r.out;
  for (int k = 0; k < 2; ++k) {
    const std::string stem = "f.vehicle_" + std::to_string(k);
    EXPECT_TRUE(fs::exists(dir / (stem + "_instructions.md"))) << stem;
    EXPECT_TRUE(fs::exists(dir / (stem + "_instructions.csv"))) << stem;
    EXPECT_FALSE(fs::exists(dir / (stem + ".gpx"))) << stem;
  }
}

}  // namespace
}  // namespace slamroute::test
