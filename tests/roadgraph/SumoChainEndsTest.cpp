// The ends of a graph edge's SUMO chain (SumoEdgeMapping.cpp).
//
// Connectors (dropConnectorEnds), on the stub net: its east arm C -> M ends at the T junction M,
// whose dead-end stub to A has 0.2 m edges M_A / A_M. With the U-turn at A cut, A_M is entered from
// nowhere but the stub, like Bologna's 203[1]b at junction 3. A graph node X placed 15 m east of M
// (past the stub, as the builder placed one past Bologna's junction 3) splits the drive C -> M -> Q
// into C -> X and X -> Q; their lanes near X are the stub's. The known answer: the chains are the
// streets, C_M and M_Q, and the turn C -> X -> Q is the net's left turn C_M -> M_Q.
//
// Lanes of another arm (dropBridgedEnds), on the plus net: a graph edge from a node X in the
// centre's junction box, 3 m north of C, runs 9 m north and then west at y = 512 to Y
// (350, 512), as where a junction's node lies off the point where its arms meet. One sample
// falls on the north arm's C_N, which SUMO joins to C_W only by turning round at N. The known
// answer: the chain is C_W.
//
// Bridges (drivableChain), on the default city: a sample on the opposite lane at a corner.
#include <gtest/gtest.h>
#include "TestTmp.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "slamroute/core/SumoNet.hpp"
#include "slamroute/roadgraph/SumoMatch.hpp"

namespace slamroute::roadgraph {
namespace {

namespace fs = std::filesystem;

/// The stub net without the U-turn M_A -> A_M at the stub's end.
SumoNet stubWithoutUTurn() {
  std::ifstream in(fs::path(SLAMROUTE_SOURCE_DIR) / "networks/test/stub.net.xml");
  std::string xml((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string key = "<connection from=\"M_A\" to=\"A_M\"";
  const auto at = xml.find(key);
  if (at == std::string::npos) throw std::runtime_error("stub.net.xml: no connection M_A -> A_M");
  xml.erase(at, xml.find('\n', at) - at);
  const fs::path path = slamroute::test::testTmp() / "stub.net.xml";
  std::ofstream(path) << xml;
  return SumoNet::read(path);
}

/// Nodes C (500, 500), X (655, 500), Q (640, 620); edges C -> X along the east arm and X -> Q
/// back west past the stub and north up M_Q.
RoadGraph graphPastTheStub() {
  RoadGraph g;
  g.nodes = {
      {0, Point3(500, 500, 0), ""}, {1, Point3(655, 500, 0), ""}, {2, Point3(640, 620, 0), ""}};
  const auto edge = [&](int id, int u, int v, Polyline pl) {
    RoadEdge e;
    e.id = id;
    e.u = u;
    e.v = v;
    e.length_m = polylineLength(pl);
    e.polyline = std::move(pl);
    e.street = id;
    g.edges.push_back(std::move(e));
  };
  edge(0, 0, 1, {Point3(500, 500, 0), Point3(655, 500, 0)});
  edge(1, 1, 2, {Point3(655, 500, 0), Point3(641.6, 500, 0), Point3(641.6, 620, 0)});
  return g;
}

bool turnAllowed(const RoadGraph& g, int from, int to) {
  const auto& nx = g.allowed_next.at(static_cast<std::size_t>(from));
  return std::find(nx.begin(), nx.end(), to) != nx.end();
}

TEST(SumoChainEnds, ChainEndsOnAConnectorAreTheStreetsPastIt) {
  const SumoNet net = stubWithoutUTurn();
  RoadGraph g = graphPastTheStub();
  const SumoMatchConfig cfg;
  EXPECT_EQ(mapSumoEdges(g, net, cfg), 0u);
  EXPECT_EQ(g.edges[0].sumo_edges, std::vector<std::string>{"C_M"});
  EXPECT_EQ(g.edges[1].sumo_edges, std::vector<std::string>{"M_Q"});
  turnsFromNet(g, net, cfg);
  EXPECT_TRUE(turnAllowed(g, 0, 1));
}

TEST(SumoChainEnds, KeptConnectorsRefuseTheTurn) {
  // Without the rule the chains keep the stub's edges, and M_A -> A_M is no turn of the net.
  const SumoNet net = stubWithoutUTurn();
  RoadGraph g = graphPastTheStub();
  SumoMatchConfig cfg;
  cfg.connector_max_m = 0.0;
  mapSumoEdges(g, net, cfg);
  EXPECT_EQ(g.edges[0].sumo_edges, (std::vector<std::string>{"C_M", "M_A"}));
  EXPECT_EQ(g.edges[1].sumo_edges, (std::vector<std::string>{"A_M", "M_Q"}));
  turnsFromNet(g, net, cfg);
  EXPECT_FALSE(turnAllowed(g, 0, 1));
}

RoadGraph graphAcrossTheBox() {
  RoadGraph g;
  g.nodes = {{0, Point3(501.6, 503, 0), ""}, {1, Point3(350, 512, 0), ""}};
  RoadEdge e;
  e.u = 0;
  e.v = 1;
  e.polyline = {Point3(501.6, 503, 0), Point3(501.6, 512, 0), Point3(350, 512, 0)};
  e.length_m = polylineLength(e.polyline);
  g.edges.push_back(e);
  return g;
}

TEST(SumoChainEnds, WeakEndJoinedOnlyByABridgeIsDropped) {
  const SumoNet net = SumoNet::read(fs::path(SLAMROUTE_SOURCE_DIR) / "networks/test/plus.net.xml");
  RoadGraph g = graphAcrossTheBox();
  EXPECT_EQ(mapSumoEdges(g, net, SumoMatchConfig{}), 0u);
  EXPECT_EQ(g.edges[0].sumo_edges, std::vector<std::string>{"C_W"});
  // Without the rule the bridge's cost drops it too: the drive from C_N round to C_W is far
  // longer than the polyline between their samples.
  RoadGraph kept = graphAcrossTheBox();
  SumoMatchConfig cfg;
  cfg.bridged_end_max_samples = 0;
  mapSumoEdges(kept, net, cfg);
  EXPECT_EQ(kept.edges[0].sumo_edges, std::vector<std::string>{"C_W"});
}

TEST(SumoChainEnds, ASampleOnTheOppositeLaneAtACornerIsNotDrivenRoundTo) {
  // The default city's street R1C2 -> R0C2 -> T2 (survey seed 2): its centreline comes down the
  // north-south arm and bends east at R0C2 with a wiggle whose samples fall on the northbound
  // lane R0C2_R1C2 for a step. Reaching that lane and leaving it for R0C2_T2 takes a drive to T2
  // and back and one to R1C2 and back; the chain is the two streets of the corner.
  const SumoNet net =
      SumoNet::read(fs::path(SLAMROUTE_SOURCE_DIR) / "networks/default_city/default_city.net.xml");
  RoadGraph g;
  g.nodes = {{0, Point3(414.5, 219.2, 0), ""}, {1, Point3(734.6, 45.0, 0), ""}};
  RoadEdge e;
  e.u = 0;
  e.v = 1;
  e.polyline = {Point3(414.5, 219.2, 0), Point3(397.6, 52.9, 0), Point3(401.6, 38.7, 0),
                Point3(405.9, 39.9, 0),  Point3(408.5, 41.8, 0), Point3(411.8, 43.3, 0),
                Point3(421.1, 39.1, 0),  Point3(734.6, 45.0, 0)};
  e.length_m = polylineLength(e.polyline);
  g.edges.push_back(e);
  EXPECT_EQ(mapSumoEdges(g, net, SumoMatchConfig{}), 0u);
  EXPECT_EQ(g.edges[0].sumo_edges, (std::vector<std::string>{"R1C2_R0C2", "R0C2_T2"}));
}

}  // namespace
}  // namespace slamroute::roadgraph
