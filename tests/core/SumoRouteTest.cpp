#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "TestUtil.hpp"
#include "slamroute/core/SumoRoute.hpp"

namespace slamroute {
namespace {

const SumoNet& grid() {
  static const SumoNet net =
      SumoNet::read(std::string(SLAMROUTE_SOURCE_DIR) + "/networks/test/grid3x3.net.xml");
  return net;
}

TEST(SumoRoute, LegalRouteIsUnchanged) {
  const SumoNet& net = grid();
  // Find two edges joined by an allowed turn.
  for (const auto& c : net.connections) {
    if (!net.turnAllowed(c.from, c.to)) continue;
    const LegalRoute r = legalizeSumoRoute(net, {c.from, c.to});
    EXPECT_EQ(r.edges, (std::vector<std::string>{c.from, c.to}));
    EXPECT_EQ(r.repaired_transitions, 0);
    return;
  }
  FAIL() << "no connection in grid";
}

TEST(SumoRoute, GapIsBridgedWithALegalShortestDetour) {
  const SumoNet& net = grid();
  // Two edges that do not touch: first and last passenger edge in the file.
  const std::string a = net.edges.front().id, b = net.edges.back().id;
  ASSERT_FALSE(net.turnAllowed(a, b));
  const LegalRoute r = legalizeSumoRoute(net, {a, b});
  EXPECT_EQ(r.edges.front(), a);
  EXPECT_EQ(r.edges.back(), b);
  EXPECT_EQ(r.repaired_transitions, 1);
  EXPECT_EQ(firstIllegalTurn(net, r.edges), -1);
  EXPECT_GT(r.added_length_m, 0.0);
}

TEST(SumoRoute, EdgesOutsideTheDrivableCoreAreDroppedFromTheMiddle) {
  // The plus net without the turnaround at the east end: C_E becomes a dead end (only entered)
  // and E_C a source (only left), like streets leading out of a map.
  std::ifstream in(std::string(SLAMROUTE_SOURCE_DIR) + "/networks/test/plus.net.xml");
  std::string xml((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string turn = "<connection from=\"C_E\" to=\"E_C\"";
  const auto at = xml.find(turn);
  ASSERT_NE(at, std::string::npos);
  xml.erase(at, xml.find('\n', at) - at);
  const auto dir = test::tempDir("sumo_route_dead_end");
  test::writeText(dir / "plus.net.xml", xml);
  const SumoNet net = SumoNet::read(dir / "plus.net.xml");
  ASSERT_FALSE(net.turnAllowed("C_E", "E_C"));
  // A trace-built route that drove into the east arm and back: the arm is dropped.
  const LegalRoute r = legalizeSumoRoute(net, {"N_C", "C_E", "E_C", "C_S"});
  EXPECT_EQ(r.edges, (std::vector<std::string>{"N_C", "C_S"}));
  EXPECT_EQ(r.dropped_edges, 2);
  // Ending in the dead end is fine (SUMO lets a route end anywhere); leaving it is not.
  EXPECT_EQ(legalizeSumoRoute(net, {"N_C", "C_E"}).edges, (std::vector<std::string>{"N_C", "C_E"}));
  EXPECT_THROW(legalizeSumoRoute(net, {"C_E", "C_S"}), std::invalid_argument);
}

TEST(SumoRoute, UnknownEdgeIsAnError) {
  EXPECT_THROW(legalizeSumoRoute(grid(), {"nope"}), std::invalid_argument);
}

}  // namespace
}  // namespace slamroute
