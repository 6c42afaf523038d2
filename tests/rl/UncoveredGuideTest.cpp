// The guide of Q-learning's state (rl/src/UncoveredGuide.hpp) against Boost's Dijkstra on the
// turn-expanded graph (TurnPaths): following its action from any state reaches the nearest
// uncovered edge by a shortest legal path, also when the state leaves the kept path.
#include <gtest/gtest.h>

#include <set>

#include "RlTestUtil.hpp"
#include "UncoveredGuide.hpp"

namespace slamroute::rl {
namespace {

/// Length driven by following the guide from state s until an edge with is_new is driven.
template <class IsNew>
double followGuide(detail::UncoveredGuide& guide, const PlanGraph& pg, int s, const IsNew& is_new) {
  double length = 0.0;
  for (int step = 0; step <= pg.m; ++step) {
    const int e = guide.toward(s, is_new);
    if (e < 0) return -1.0;
    length += pg.len[static_cast<std::size_t>(e)];
    if (is_new(e)) return length;
    s = e;
  }
  return -1.0;
}

TEST(UncoveredGuide, FollowsShortestLegalPathsToTheNearestUncoveredNode) {
  const RoadGraph g = test::grid(4, 4);
  const PlanGraph pg = PlanGraph::build(g);
  const TurnPaths paths(pg);
  const std::set<int> uncovered = {5, 14};  // two nodes; every other node counts as visited
  auto is_new = [&](int e) { return uncovered.count(pg.v[static_cast<std::size_t>(e)]) > 0; };
  detail::UncoveredGuide guide(pg);
  for (int s = 0; s < pg.m + pg.n; ++s) {
    const bool edge_state = s < pg.m;
    const int node = edge_state ? pg.v[static_cast<std::size_t>(s)] : s - pg.m;
    const auto p = paths.toNearest(edge_state ? s : -1, node, [&](int e) { return is_new(e); });
    ASSERT_TRUE(p.has_value());
    EXPECT_NEAR(followGuide(guide, pg, s, is_new), p->length_m, 1e-6) << "state " << s;
  }
}

TEST(UncoveredGuide, NothingUncoveredGivesNoAction) {
  const PlanGraph pg = PlanGraph::build(test::grid(3, 3));
  detail::UncoveredGuide guide(pg);
  EXPECT_EQ(guide.toward(pg.m, [](int) { return false; }), -1);
}

}  // namespace
}  // namespace slamroute::rl
