// `slamroute evaluate` of a simulated drive adds the GP map completeness (explore's occupancy grid
// at the SLAM estimate) to metrics.json and writes frontier_probability.png.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "CliTestUtil.hpp"
#include "slamroute/core/AtomicFile.hpp"

namespace slamroute {
namespace {
namespace fs = std::filesystem;

TEST(MapCompletenessCli, EvaluateReportsTheUnseenShareNearTheStreets) {
  const auto dir = test::cliTempDir("map_completeness");
  const std::string net = std::string(SLAMROUTE_SOURCE_DIR) + "/networks/test/grid3x3.net.xml";
  std::ofstream(dir / "route.json") << R"(["g00_g01","g01_g11"])";
  const auto d = test::runCli("drive --net " + net + " --route " + (dir / "route.json").string() +
                              " --out " + (dir / "drive").string() + " --no-mesh --log-level warn");
  ASSERT_EQ(d.code, 0) << d.out;
  const auto e = test::runCli("--log-level warn evaluate --scan-stride 10 --drive " +
                              (dir / "drive").string() + " --out " + (dir / "eval").string());
  ASSERT_EQ(e.code, 0) << e.out;
  const auto m = nlohmann::json::parse(readFile(dir / "eval/metrics.json"))["map_completeness"];
  ASSERT_TRUE(m.is_object()) << readFile(dir / "eval/metrics.json");
  EXPECT_EQ(m["street_radius_m"].get<double>(), 30.0);
  EXPECT_GT(m["cells"].get<long long>(), 0);
  // two of the grid's twelve streets driven: much is seen, much is not, frontiers between
  const double unknown = m["unknown_share"].get<double>();
  EXPECT_GT(unknown, 0.1);
  EXPECT_LT(unknown, 0.95);
  EXPECT_GT(m["frontier_share"].get<double>(), 0.0);
  EXPECT_GT(fs::file_size(dir / "eval/frontier_probability.png"), 100u);
}

}  // namespace
}  // namespace slamroute
