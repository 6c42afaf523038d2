// Turn permissions of a graph from the net it was matched to (SumoTurns.cpp), on the plus net:
// a hand-made graph whose edges are the net's own edges, so the known answer is the net's
// <connection>s.
#include <gtest/gtest.h>
#include "TestTmp.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>

#include "slamroute/core/SumoNet.hpp"
#include "slamroute/roadgraph/SumoMatch.hpp"

namespace slamroute::roadgraph {
namespace {

namespace fs = std::filesystem;

/// The plus net with some <connection from=A to=B> lines removed.
SumoNet plusWithout(const std::vector<std::pair<std::string, std::string>>& cut,
                    const std::string& name) {
  std::ifstream in(fs::path(SLAMROUTE_SOURCE_DIR) / "networks/test/plus.net.xml");
  std::string xml((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (const auto& [a, b] : cut) {
    const std::string key = "<connection from=\"" + a + "\" to=\"" + b + "\"";
    const auto at = xml.find(key);
    if (at == std::string::npos) throw std::runtime_error("no connection " + a + " -> " + b);
    xml.erase(at, xml.find('\n', at) - at);
  }
  const fs::path dir = slamroute::test::testTmp() / ("sumo_turns_" + name);
  fs::create_directories(dir);
  std::ofstream(dir / "plus.net.xml") << xml;
  return SumoNet::read(dir / "plus.net.xml");
}

/// One graph node per junction, one graph edge per SUMO edge (street = the undirected pair).
RoadGraph graphOf(const SumoNet& net) {
  RoadGraph g;
  std::map<std::string, int> node;
  for (const auto& j : net.junctions) {
    node[j.id] = static_cast<int>(g.nodes.size());
    g.nodes.push_back({static_cast<int>(g.nodes.size()), j.pos, j.id});
  }
  std::map<std::pair<int, int>, int> street;
  for (const auto& e : net.edges) {
    if (e.isInternal()) continue;
    RoadEdge re;
    re.id = static_cast<int>(g.edges.size());
    re.u = node.at(e.from);
    re.v = node.at(e.to);
    re.polyline = e.shape;
    re.length_m = e.length();
    re.sumo_edges = {e.id};
    const auto key = std::make_pair(std::min(re.u, re.v), std::max(re.u, re.v));
    re.street = street.emplace(key, static_cast<int>(street.size())).first->second;
    g.edges.push_back(re);
  }
  return g;
}

int edgeId(const RoadGraph& g, const std::string& sumo) {
  for (const auto& e : g.edges)
    if (e.sumo_edges.front() == sumo) return e.id;
  return -1;
}

bool allowed(const RoadGraph& g, const std::string& a, const std::string& b) {
  const auto& nx = g.allowed_next.at(static_cast<std::size_t>(edgeId(g, a)));
  return std::find(nx.begin(), nx.end(), edgeId(g, b)) != nx.end();
}

TEST(SumoTurns, FollowTheNetsConnections) {
  // No U-turn at the centre coming from the north; no turnaround at the east end.
  const SumoNet net = plusWithout({{"N_C", "C_N"}, {"C_E", "E_C"}}, "cut");
  RoadGraph g = graphOf(net);
  const TurnStats st = turnsFromNet(g, net, SumoMatchConfig{});
  EXPECT_TRUE(g.restricted_turns);
  // 4 in x 4 out at the centre, 1 x 1 at each arm end.
  EXPECT_EQ(st.candidate_turns, 20u);
  EXPECT_EQ(st.forbidden_turns, 2u);
  EXPECT_FALSE(allowed(g, "N_C", "C_N"));
  EXPECT_FALSE(allowed(g, "C_E", "E_C"));
  EXPECT_TRUE(allowed(g, "N_C", "C_S"));
  EXPECT_TRUE(allowed(g, "N_C", "C_E"));
  EXPECT_TRUE(allowed(g, "E_C", "C_E"));  // this U-turn is still in the net
  EXPECT_TRUE(allowed(g, "C_N", "N_C"));  // turnaround at the north end
  // A short detour counts as the turn: with a 400 m budget, N_C -> C_N is allowed by going
  // round the west arm (C_W then W_C: 300 m of edges in between).
  SumoMatchConfig wide;
  wide.turn_max_detour_m = 400.0;
  RoadGraph g2 = graphOf(net);
  turnsFromNet(g2, net, wide);
  EXPECT_TRUE(allowed(g2, "N_C", "C_N"));
  EXPECT_FALSE(allowed(g2, "C_E", "E_C"));  // nothing leaves the dead end
}

TEST(SumoTurns, EdgesWithoutSumoEdgesKeepAllButStraightBack) {
  const SumoNet net = plusWithout({}, "none");
  RoadGraph g = graphOf(net);
  g.edges[static_cast<std::size_t>(edgeId(g, "C_E"))].sumo_edges.clear();
  g.edges[static_cast<std::size_t>(edgeId(g, "E_C"))].sumo_edges.clear();
  turnsFromNet(g, net, SumoMatchConfig{});
  // C_E (now unmapped) leads on to E_C only, which is straight back: forbidden.
  int c_e = -1, e_c = -1;
  for (const auto& e : g.edges)
    if (e.sumo_edges.empty())
      (g.nodes[static_cast<std::size_t>(e.u)].sumo_junction == "C" ? c_e : e_c) = e.id;
  ASSERT_GE(c_e, 0);
  ASSERT_GE(e_c, 0);
  EXPECT_TRUE(g.allowed_next[static_cast<std::size_t>(c_e)].empty());
  // Into an unmapped edge from a mapped one: allowed (N_C -> C_E).
  const auto& from_n = g.allowed_next[static_cast<std::size_t>(edgeId(g, "N_C"))];
  EXPECT_NE(std::find(from_n.begin(), from_n.end(), c_e), from_n.end());
}

}  // namespace
}  // namespace slamroute::roadgraph
