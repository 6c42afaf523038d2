// EIF uncertainty model (R_U, eq. 6): grows when driving, shrinks at loop closures.
#include <gtest/gtest.h>

#include "RlTestUtil.hpp"
#include "slamroute/rl/Eif.hpp"

namespace slamroute::rl {
namespace {

TEST(Eif, GrowsMonotonicallyOnLoopFreePath) {
  EifConfig cfg;
  PoseEif f(cfg);
  double prev = f.logDetCov();
  const double headings[] = {0.0, 0.5, 1.57, -2.0, 3.0, 0.1, 0.0, 2.2};
  for (int i = 0; i < 40; ++i) {
    f.drive(edgeMotion(cfg, 50.0 + 10.0 * (i % 5), headings[i % 8], 0.3 + 0.1 * (i % 7)));
    const double now = f.logDetCov();
    EXPECT_GT(now, prev) << "step " << i;
    prev = now;
  }
}

TEST(Eif, PoorWeightAndLengthGrowFaster) {
  EifConfig cfg;
  PoseEif good(cfg), poor(cfg), longer(cfg);
  good.drive(edgeMotion(cfg, 100.0, 0.0, 1.0));
  poor.drive(edgeMotion(cfg, 100.0, 0.0, 0.2));
  longer.drive(edgeMotion(cfg, 300.0, 0.0, 1.0));
  EXPECT_GT(poor.logDetCov(), good.logDetCov());
  EXPECT_GT(longer.logDetCov(), good.logDetCov());
}

TEST(Eif, RevisitShrinks) {
  EifConfig cfg;
  PoseEif f(cfg);
  const Info3 at_start = f.info();
  for (int i = 0; i < 4; ++i) f.drive(edgeMotion(cfg, 100.0, 1.5708 * i, 0.8));
  const double before = f.logDetCov();
  f.closeLoop(at_start);
  EXPECT_LT(f.logDetCov(), before);
  // Information only adds: the pose block stays positive definite.
  EXPECT_GT(f.info().determinant(), 0.0);
}

TEST(Eif, RouteMetricsShowTheClosure) {
  // Around one 100 m block of a 2x2 grid and back to the start: the last step is a loop closure.
  const RoadGraph g = test::grid(2, 2);
  const PlanGraph pg = PlanGraph::build(g);
  // Local ids equal RoadGraph ids here (all kept, in order). Find 0->1->3->2->0.
  auto edge = [&](int a, int b) {
    for (int e = 0; e < pg.m; ++e)
      if (pg.node_orig[pg.u[e]] == a && pg.node_orig[pg.v[e]] == b) return e;
    return -1;
  };
  const std::vector<int> loop = {edge(0, 1), edge(1, 3), edge(3, 2), edge(2, 0)};
  Route r;
  EifConfig cfg;
  cfg.loop_min_travel_m = 350.0;
  fillRouteMetrics(pg, g, pg.node_local[0], loop, cfg, r);
  ASSERT_EQ(r.logdet_cov_along.size(), 4u);
  EXPECT_LT(r.logdet_cov_along[0], r.logdet_cov_along[1]);
  EXPECT_LT(r.logdet_cov_along[1], r.logdet_cov_along[2]);
  EXPECT_LT(r.logdet_cov_along[3], r.logdet_cov_along[2]);
  EXPECT_EQ(r.revisits, 1);
  EXPECT_EQ(r.loop_closures, 1);
  EXPECT_DOUBLE_EQ(r.length_m, 400.0);
  EXPECT_DOUBLE_EQ(r.node_coverage_pct, 100.0);
  EXPECT_DOUBLE_EQ(r.edge_coverage_pct, 100.0);
}

}  // namespace
}  // namespace slamroute::rl
