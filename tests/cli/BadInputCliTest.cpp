// Inputs that used to run to a wrong result or fail with a library's raw text: each is now one
// line naming the file (or option) and the problem, a non-zero exit and nothing written.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "CliTestUtil.hpp"
#include "slamroute/core/AtomicFile.hpp"

namespace slamroute {
namespace {
namespace fs = std::filesystem;

const std::string kGrid = std::string(SLAMROUTE_SOURCE_DIR) + "/networks/test/grid3x3.net.xml";

void put(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

TEST(BadInputCli, ConfigValuesThatCannotWorkAreRejectedWhenLoaded) {
  const auto dir = test::cliTempDir("bad_config_values");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"roadgraph:\n  depth:\n    normal_neighbours: 0\n",
       "roadgraph.depth.normal_neighbours must be in [3, 1000] (got 0)"},
      {"roadgraph:\n  nodes:\n    min_branches: 0\n", "roadgraph.nodes.min_branches must be"},
      {"simulate:\n  drive:\n    traffic_per_km: 1e9\n", "simulate.drive.traffic_per_km must be"},
      {"simulate:\n  survey:\n    noise_sigma_m: -0.5\n", "simulate.survey.noise_sigma_m must be"},
      {"rl:\n  eif:\n    long_var_per_m: -0.001\n", "rl.eif.long_var_per_m must be"},
      {"simulate:\n  depth:\n    width: 0\n", "simulate.depth.width must be"},
  };
  for (const auto& [yaml, fragment] : cases) {
    put(dir / "c.yaml", yaml);
    test::expectCleanFailure("--config " + (dir / "c.yaml").string() + " config --dump",
                             (dir / "c.yaml").string() + ": " + fragment, dir, 1);
  }
}

TEST(BadInputCli, OptionsAndCommandsAreNamed) {
  const auto dir = test::cliTempDir("bad_options");
  fs::create_directories(dir / "cfgdir");
  test::expectCleanFailure("--config " + (dir / "cfgdir").string() + " config --dump",
                           "cfgdir: is a folder, not a file", dir, 1);
  for (const char* seed : {"-1", "18446744073709551616", "12abc"})
    test::expectCleanFailure(std::string("--seed ") + seed + " config --dump",
                             std::string("--seed: '") + seed + "' is not a whole number", dir, 1);
  test::expectCleanFailure("frobnicate --net x", "unknown command 'frobnicate'", dir, 1);
  const auto ok = test::runCli("--seed 18446744073709551615 config --dump");
  EXPECT_EQ(ok.code, 0) << ok.out;
  EXPECT_NE(ok.out.find("seed: 18446744073709551615"), std::string::npos) << ok.out;
}

TEST(BadInputCli, OutputPathsThatCannotBeWritten) {
  const auto dir = test::cliTempDir("bad_outputs");
  fs::create_directories(dir / "routes");
  test::expectCleanFailure("--log-level warn plan --net " + kGrid + " --planner postman --out " +
                               (dir / "routes").string(),
                           "routes: is a folder; give a file name to write", dir, 1);
  EXPECT_TRUE(fs::is_empty(dir / "routes"));
  put(dir / "file", "x");
  test::expectCleanFailure("run --net " + kGrid + " --out " + (dir / "file" / "run").string(),
                           (dir / "file").string() + "/run/logs: Not a directory", dir, 2);
  const std::string traces = "t,vehicle,x,y\n0,a,0,0\n1,a,10,0\n";
  put(dir / "traces.csv", traces);
  test::expectCleanFailure("build-graph --traces " + (dir / "traces.csv").string() + " --out " +
                               (dir / "traces.csv").string(),
                           "traces.csv: is an input of build-graph", dir, 3);
  EXPECT_EQ(readFile(dir / "traces.csv"), traces);
}

TEST(BadInputCli, NumbersNoFileCanHold) {
  const auto dir = test::cliTempDir("bad_numbers");
  put(dir / "g.json", R"({"nodes":[{"id":0,"x":1e400,"y":0}],"edges":[]})");
  test::expectCleanFailure(
      "plan --graph " + (dir / "g.json").string() + " --out " + (dir / "r.json").string(),
      "g.json: not valid JSON (number overflow parsing '1e400')", dir, 1);
  put(dir / "dup.tum", "0 0 0 0 0 0 0 1\n0.1 1 0 0 0 0 0 1\n0.1 2 0 0 0 0 0 1\n");
  test::expectCleanFailure(
      "compare " + (dir / "dup.tum").string() + " " + (dir / "dup.tum").string(),
      "dup.tum:3: time 0.100000 s is not later than the pose before", dir, 2);
  put(dir / "far.tum", "0 0 0 0 0 0 0 1\n0.1 1e300 0 0 0 0 0 1\n");
  test::expectCleanFailure(
      "compare " + (dir / "far.tum").string() + " " + (dir / "dup.tum").string(),
      "far.tum:2: coordinates must be finite and within 10,000 km", dir, 3);
  put(dir / "zero.txt", "1 0 0 0 0 1 0 0 0 0 1 0\n0 0 0 1 0 0 0 0 0 0 0 0\n");
  test::expectCleanFailure(
      "compare " + (dir / "zero.txt").string() + " " + (dir / "dup.tum").string(),
      "zero.txt:2: the 3x3 part is not a rotation matrix", dir, 4);
  // A shape point 100,000 km out used to make survey's world builder loop for ever.
  std::string net = readFile(kGrid);
  const auto shape = net.find("shape=\"", net.find("<edge id=\"g00_g01\"")) + 7;
  net.insert(shape, "1e8,0 ");
  put(dir / "far.net.xml", net);
  test::expectCleanFailure(
      "survey --net " + (dir / "far.net.xml").string() + " --out " + (dir / "survey").string(),
      "far.net.xml: edge 'g00_g01': bad shape point '1e8,0'", dir, 5);
}

TEST(BadInputCli, PlanReplacesRouteJsonAndRouXmlTogether) {
  // A route on a graph without SUMO edges after one on the net: the older r.rou.xml must not stay
  // beside an r.json it does not belong to.
  const auto dir = test::cliTempDir("plan_file_set");
  const auto first = test::runCli("--log-level warn plan --net " + kGrid +
                                  " --planner postman --out " + (dir / "r.json").string());
  ASSERT_EQ(first.code, 0) << first.out;
  ASSERT_TRUE(fs::exists(dir / "r.rou.xml"));
  put(dir / "g.json", R"({"nodes":[{"id":0,"x":0,"y":0},{"id":1,"x":100,"y":0}],"edges":[)"
                      R"({"id":0,"u":0,"v":1,"length":100},{"id":1,"u":1,"v":0,"length":100}]})");
  const auto second = test::runCli("--log-level warn plan --graph " + (dir / "g.json").string() +
                                   " --planner postman --out " + (dir / "r.json").string());
  ASSERT_EQ(second.code, 0) << second.out;
  EXPECT_FALSE(fs::exists(dir / "r.rou.xml"));
  EXPECT_TRUE(nlohmann::json::parse(readFile(dir / "r.json"))["sumo_edges"].empty());
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  EXPECT_EQ(n, 2u);  // g.json and r.json: no staged file left
}

}  // namespace
}  // namespace slamroute
