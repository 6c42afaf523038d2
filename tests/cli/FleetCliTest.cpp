// A fleet's drive and evaluation through the CLI: bad fleet files fail with one line naming the
// file and the vehicle, and write nothing.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "CliTestUtil.hpp"

namespace slamroute {
namespace {
namespace fs = std::filesystem;

const std::string kGrid = std::string(SLAMROUTE_SOURCE_DIR) + "/networks/test/grid3x3.net.xml";

TEST(FleetCli, ARouteWithAnUnknownEdgeNamesTheVehicleAndWritesNothing) {
  const auto dir = test::cliTempDir("fleet_bad_route");
  const nlohmann::json route = {
      {"vehicles",
       {{{"planner", "manual"}, {"sumo_edges", {"g00_g01", "g01_g02"}}},
        {{"planner", "manual"}, {"sumo_edges", {"g00_g10", "no_such_edge"}}}}}};
  std::ofstream(dir / "route.json") << route.dump();
  test::expectCleanFailure("drive --net " + kGrid + " --route " + (dir / "route.json").string() +
                               " --out " + (dir / "drive").string(),
                           "route.json (vehicle 1)", dir, 1);
}

TEST(FleetCli, AFleetFolderWithAMissingVehicleFolderIsNamed) {
  const auto dir = test::cliTempDir("fleet_bad_folder");
  fs::create_directories(dir / "drive" / "vehicle_0");
  const nlohmann::json fleet = {{"net", kGrid},
                                {"seed", 1},
                                {"vehicles",
                                 {{{"id", "mapper_0"},
                                   {"folder", "vehicle_0"},
                                   {"route_length_m", 1.0},
                                   {"driven_m", 1.0},
                                   {"depart_s", 0.0},
                                   {"arrive_s", 1.0},
                                   {"frames", 10}},
                                  {{"id", "mapper_1"},
                                   {"folder", "vehicle_1"},
                                   {"route_length_m", 1.0},
                                   {"driven_m", 1.0},
                                   {"depart_s", 0.0},
                                   {"arrive_s", 1.0},
                                   {"frames", 10}}}}};
  std::ofstream(dir / "drive" / "fleet.json") << fleet.dump();
  test::expectCleanFailure(
      "evaluate --drive " + (dir / "drive").string() + " --out " + (dir / "eval").string(),
      "fleet.json: vehicle folder 'vehicle_1' does not exist", dir, 1);
}

}  // namespace
}  // namespace slamroute
