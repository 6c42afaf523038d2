#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>

#include "SumoToolsNets.hpp"
#include "TestUtil.hpp"
#include "slamroute/core/AtomicFile.hpp"
#include "slamroute/core/RoadGraph.hpp"
#include "slamroute/core/SumoNet.hpp"

namespace slamroute {
namespace {

RoadGraph square() {
  // 4 nodes on a 100 m square, two-way streets: 8 directed edges, 4 streets.
  RoadGraph g;
  const Point3 p[4] = {{0, 0, 0}, {100, 0, 0}, {100, 100, 0}, {0, 100, 0}};
  for (int i = 0; i < 4; ++i) g.nodes.push_back({i, p[i], ""});
  for (int i = 0; i < 4; ++i) {
    const int j = (i + 1) % 4;
    g.edges.push_back({static_cast<int>(g.edges.size()), i, j, 100.0, 0.5, {p[i], p[j]}, {}, i});
    g.edges.push_back({static_cast<int>(g.edges.size()), j, i, 100.0, 0.5, {p[j], p[i]}, {}, i});
  }
  return g;
}

TEST(RoadGraph, JsonRoundTrip) {
  const auto dir = test::tempDir("roadgraph_json");
  RoadGraph g = square();
  g.edges[3].weight = 0.9;
  g.edges[3].sumo_edges = {"e1", "e2"};
  g.metadata_json = R"({"node_precision":1.0})";
  g.writeJson(dir / "g.json");
  const RoadGraph r = RoadGraph::readJson(dir / "g.json");
  ASSERT_EQ(r.nodes.size(), 4u);
  ASSERT_EQ(r.edges.size(), 8u);
  EXPECT_DOUBLE_EQ(r.edges[3].weight, 0.9);
  EXPECT_EQ(r.edges[3].sumo_edges, (std::vector<std::string>{"e1", "e2"}));
  EXPECT_EQ(r.edges[3].street, 1);
  EXPECT_FALSE(r.restricted_turns);
  EXPECT_DOUBLE_EQ(r.totalLength(), 800.0);
  EXPECT_EQ(nlohmann::json::parse(r.metadata_json)["node_precision"], 1.0);
  // Unrestricted: after edge 0 (0->1) one may take 1->2 or the U-turn 1->0.
  EXPECT_EQ(r.nextEdges(0).size(), 2u);
}

TEST(RoadGraph, FromSumoNetKeepsTurnPermissions) {
  const SumoNet net = SumoNet::read(test::bolognaNet());
  const RoadGraph g = RoadGraph::fromSumoNet(net, true);
  EXPECT_EQ(g.nodes.size(), 81u);
  EXPECT_EQ(g.edges.size(), 135u);
  ASSERT_TRUE(g.restricted_turns);
  g.validate("bologna");
  // allowed_next is exactly the set of SUMO connections between edges of the kept part.
  const auto out = g.outEdges();
  for (const auto& e : g.edges) {
    std::vector<int> expect;
    for (int nx : out[static_cast<std::size_t>(e.v)])
      if (net.turnAllowed(e.sumo_edges[0], g.edges[static_cast<std::size_t>(nx)].sumo_edges[0]))
        expect.push_back(nx);
    auto got = g.allowed_next[static_cast<std::size_t>(e.id)];
    std::sort(got.begin(), got.end());
    std::sort(expect.begin(), expect.end());
    EXPECT_EQ(got, expect) << "edge " << e.sumo_edges[0];
  }
}

TEST(RoadGraph, ExportsGeoJsonGraphMLAndPng) {
  const auto dir = test::tempDir("roadgraph_export");
  const RoadGraph g = square();
  g.writeGeoJson(dir / "g.geojson");
  g.writeGraphML(dir / "g.graphml");
  g.renderPng(dir / "g.png");
  const auto gj = nlohmann::json::parse(readFile(dir / "g.geojson"));
  EXPECT_EQ(gj["features"].size(), 12u);  // 4 points + 8 lines
  const std::string gm = readFile(dir / "g.graphml");
  EXPECT_NE(gm.find("<graphml"), std::string::npos);
  EXPECT_NE(gm.find("weight"), std::string::npos);
  const std::string png = readFile(dir / "g.png");
  ASSERT_GT(png.size(), 8u);
  EXPECT_EQ(png.substr(1, 3), "PNG");
}

TEST(RoadGraph, BadJsonIsRejectedWithTheFileName) {
  const auto dir = test::tempDir("roadgraph_bad");
  test::writeText(dir / "a.json", "{not json");
  EXPECT_THROW(RoadGraph::readJson(dir / "a.json"), std::invalid_argument);
  test::writeText(dir / "b.json",
                  R"({"nodes":[{"id":0,"x":0,"y":0}],"edges":[{"id":0,"u":0,"v":5,"length":1}]})");
  try {
    RoadGraph::readJson(dir / "b.json");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("b.json"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("missing node"), std::string::npos);
  }
}

}  // namespace
}  // namespace slamroute
