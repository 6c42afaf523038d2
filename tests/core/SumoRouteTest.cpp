#include <gtest/gtest.h>

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

TEST(SumoRoute, UnknownEdgeIsAnError) {
  EXPECT_THROW(legalizeSumoRoute(grid(), {"nope"}), std::invalid_argument);
}

}  // namespace
}  // namespace slamroute
