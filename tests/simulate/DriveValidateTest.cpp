// validateRoute: bad routes are rejected before SUMO starts, naming the edge (no SUMO).
#include <gtest/gtest.h>

#include <filesystem>

#include "slamroute/core/SumoNet.hpp"
#include "slamroute/simulate/Drive.hpp"

namespace {
using namespace slamroute;

SumoNet grid() {
  return SumoNet::read(std::filesystem::path(SLAMROUTE_SOURCE_DIR) /
                       "networks/test/grid3x3.net.xml");
}

std::string errorOf(const std::vector<std::string>& edges) {
  try {
    simulate::validateRoute(grid(), edges, "route.json");
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(DriveValidate, AcceptsAConnectedRoute) {
  EXPECT_EQ(errorOf({"g00_g01", "g01_g02", "g02_g12", "g12_g11"}), "");
}

TEST(DriveValidate, RejectsEmptyMissingEdgeAndForbiddenTurn) {
  EXPECT_NE(errorOf({}).find("route.json: route is empty"), std::string::npos);
  const std::string missing = errorOf({"g00_g01", "nowhere"});
  EXPECT_NE(missing.find("'nowhere'"), std::string::npos) << missing;
  EXPECT_NE(missing.find("position 1"), std::string::npos) << missing;
  // g00_g01 ends at g01; g10_g11 starts at g10: no connection.
  const std::string turn = errorOf({"g00_g01", "g10_g11"});
  EXPECT_NE(turn.find("'g00_g01' -> 'g10_g11'"), std::string::npos) << turn;
  EXPECT_NE(turn.find("not allowed"), std::string::npos) << turn;
}

}  // namespace
