// validateRoute: bad routes are rejected before SUMO starts, naming the edge (no SUMO).
#include <gtest/gtest.h>

#include <filesystem>

#include "slamroute/core/SumoNet.hpp"
#include "slamroute/core/SumoRoute.hpp"
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

TEST(DriveValidate, JoinsAForbiddenTurnByALegalDetourUnlessStrict) {
  const SumoNet net = grid();
  const std::vector<std::string> gap{"g00_g01", "g10_g11"};
  const auto joined = simulate::drivableRoute(net, gap, "route.json", true);
  ASSERT_GT(joined.size(), 2u);
  EXPECT_EQ(joined.front(), "g00_g01");
  EXPECT_EQ(joined.back(), "g10_g11");
  EXPECT_EQ(firstIllegalTurn(net, joined), -1);
  // A legal route is returned unchanged.
  const std::vector<std::string> ok{"g00_g01", "g01_g02", "g02_g12"};
  EXPECT_EQ(simulate::drivableRoute(net, ok, "route.json", true), ok);
  // Strict: the same gap is an error naming the file and the turn.
  try {
    simulate::drivableRoute(net, gap, "route.json", false);
    FAIL() << "strict mode accepted a forbidden turn";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("route.json: turn 'g00_g01' -> 'g10_g11'"),
              std::string::npos)
        << e.what();
  }
  // A missing edge is still an error in the joining mode, naming the file.
  try {
    simulate::drivableRoute(net, {"g00_g01", "nowhere"}, "route.json", true);
    FAIL() << "a missing edge was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("route.json: edge 'nowhere'"), std::string::npos)
        << e.what();
  }
}

}  // namespace
