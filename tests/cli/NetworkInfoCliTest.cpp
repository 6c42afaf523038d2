#include <gtest/gtest.h>

#include <filesystem>

#include <nlohmann/json.hpp>

#include "CliTestUtil.hpp"
#include "SumoToolsNets.hpp"

namespace slamroute {
namespace {

TEST(NetworkInfoCli, BolognaJson) {
  const auto r = test::runCli("network-info --json " + test::bolognaNet().string());
  ASSERT_EQ(r.code, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["junctions"], 112);
  EXPECT_EQ(j["passenger_edges"], 166);
  EXPECT_EQ(j["lscc_junctions"], 81);
  EXPECT_EQ(j["lscc_edges"], 135);
}

TEST(NetworkInfoCli, ExportsWrittenWhenAsked) {
  const auto dir = test::cliTempDir("netinfo_export");
  const auto r = test::runCli("network-info " + std::string(SLAMROUTE_SOURCE_DIR) +
                              "/networks/test/plus.net.xml --geojson " +
                              (dir / "g.geojson").string() + " --graphml " +
                              (dir / "g.graphml").string() + " --png " + (dir / "g.png").string());
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_TRUE(std::filesystem::exists(dir / "g.geojson"));
  EXPECT_TRUE(std::filesystem::exists(dir / "g.graphml"));
  EXPECT_TRUE(std::filesystem::exists(dir / "g.png"));
}

void expectOneLineError(const std::string& args, const std::string& fragment) {
  const auto r = test::runCli(args);
  EXPECT_NE(r.code, 0) << args << "\n" << r.out;
  EXPECT_EQ(test::countLines(r.out), 1) << r.out;
  EXPECT_NE(r.out.find(fragment), std::string::npos) << r.out;
}

TEST(NetworkInfoCli, BadInputs) {
  const auto dir = test::cliTempDir("netinfo_bad");
  expectOneLineError("network-info " + (dir / "none.net.xml").string(),
                     "none.net.xml: file not found");
  std::ofstream(dir / "junk.net.xml") << "junk";
  expectOneLineError("network-info " + (dir / "junk.net.xml").string(), "not valid XML");
  std::ofstream(dir / "r.net.xml") << "<routes/>";
  expectOneLineError("network-info " + (dir / "r.net.xml").string(), "not a SUMO network");
  std::ofstream(dir / "empty.net.xml")
      << "<net><junction id=\"a\" type=\"dead_end\" x=\"0\" y=\"0\"/></net>";
  expectOneLineError("network-info " + (dir / "empty.net.xml").string(),
                     "no edge open to passenger cars");
  std::ofstream(dir / "t.net.xml.gz") << "\x1f\x8b\x08\x00\x00\x00\x00\x00";
  expectOneLineError("network-info " + (dir / "t.net.xml.gz").string(), "gzip");
}

TEST(ConfigCli, DumpIsValidYamlAndRoundTrips) {
  const auto dir = test::cliTempDir("config");
  const auto r = test::runCli("config --dump");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("seed: 42"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("roadgraph:"), std::string::npos);
  std::ofstream(dir / "c.yaml") << r.out;
  const auto again =
      test::runCli("--config " + (dir / "c.yaml").string() + " --seed 7 config --dump");
  ASSERT_EQ(again.code, 0) << again.out;
  EXPECT_NE(again.out.find("seed: 7"), std::string::npos);
  std::ofstream(dir / "bad.yaml") << "roadgraph:\n  no_such_key: 1\n";
  expectOneLineError("--config " + (dir / "bad.yaml").string() + " config --dump",
                     "unknown key 'no_such_key'");
  expectOneLineError("--config " + (dir / "missing.yaml").string() + " config --dump",
                     "config file not found");
}

TEST(Cli, HelpEverywhere) {
  for (const char* sub : {"", "network-info", "survey", "build-graph", "plan", "drive", "evaluate",
                          "compare", "run", "config"}) {
    const auto r = test::runCli(std::string(sub) + " --help");
    EXPECT_EQ(r.code, 0) << sub << "\n" << r.out;
    EXPECT_NE(r.out.find("Usage"), std::string::npos) << sub;
  }
}

}  // namespace
}  // namespace slamroute
