// fleet.json of a fleet's drive folder: written and read back, the makespan, bad files named.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "TestTmp.hpp"
#include "slamroute/core/FleetDrive.hpp"

namespace {
namespace fs = std::filesystem;
using namespace slamroute;

FleetDriveInfo twoVehicles() {
  FleetDriveInfo f;
  f.net = "/nets/grid.net.xml";
  f.seed = 9;
  f.vehicles = {{"mapper_0", "vehicle_0", 1200.0, 1190.5, 0.1, 300.0, 2999},
                {"mapper_1", "vehicle_1", 900.0, 905.0, 2.3, 410.5, 4082}};
  return f;
}

TEST(FleetDriveInfo, WrittenAndReadBackWithTheMakespanFromFirstDepartureToLastArrival) {
  const fs::path dir = test::testTmp() / "fleet_info";
  fs::remove_all(dir);
  fs::create_directories(dir / "vehicle_0");
  fs::create_directories(dir / "vehicle_1");
  const FleetDriveInfo f = twoVehicles();
  EXPECT_DOUBLE_EQ(f.makespanSeconds(), 410.4);
  f.write(dir);
  ASSERT_TRUE(FleetDriveInfo::isFleetFolder(dir));
  const FleetDriveInfo g = FleetDriveInfo::read(dir);
  EXPECT_EQ(g.net, f.net);
  EXPECT_EQ(g.seed, 9u);
  ASSERT_EQ(g.vehicles.size(), 2u);
  EXPECT_EQ(g.vehicles[1].id, "mapper_1");
  EXPECT_EQ(g.vehicles[1].folder, "vehicle_1");
  EXPECT_DOUBLE_EQ(g.vehicles[1].arrive_s, 410.5);
  EXPECT_EQ(g.vehicles[0].frames, 2999u);
}

TEST(FleetDriveInfo, MissingFoldersAndFieldsAreNamed) {
  const fs::path dir = test::testTmp() / "fleet_info_bad";
  fs::remove_all(dir);
  fs::create_directories(dir / "vehicle_0");
  twoVehicles().write(dir);
  try {
    FleetDriveInfo::read(dir);
    FAIL() << "vehicle_1 is missing";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("fleet.json: vehicle folder 'vehicle_1' does not exist"),
              std::string::npos)
        << e.what();
  }
  std::ofstream(dir / "fleet.json") << R"({"net": "x", "seed": 1, "vehicles": [{"id": "a"}]})";
  EXPECT_THROW(FleetDriveInfo::read(dir), std::invalid_argument);
  std::ofstream(dir / "fleet.json") << R"({"net": "x", "seed": 1, "vehicles": []})";
  EXPECT_THROW(FleetDriveInfo::read(dir), std::invalid_argument);
  EXPECT_FALSE(FleetDriveInfo::isFleetFolder(dir / "vehicle_0"));
}

}  // namespace
