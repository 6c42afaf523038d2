// GP map completeness of a drive: unknown and frontier share near the streets of the plus net.
#include <gtest/gtest.h>

#include <cmath>

#include "TestTmp.hpp"
#include "slamroute/core/SumoNet.hpp"
#include "slamroute/explore/MapCompleteness.hpp"

namespace slamroute::explore {
namespace {

/// Scans of flat ground: every 1 m grid point within `radius` of the sensor, 1.8 m below it.
class GroundDiscScans : public ScanSource {
 public:
  GroundDiscScans(std::size_t n, double radius) : n_(n), radius_(radius) {}
  std::size_t size() const override { return n_; }
  double time(std::size_t i) const override { return 0.1 * static_cast<double>(i); }
  LidarSpec spec() const override { return LidarSpec{}; }
  Scan scan(std::size_t) const override {
    Scan s;
    for (double x = -radius_; x <= radius_; x += 1.0)
      for (double y = -radius_; y <= radius_; y += 1.0)
        if (std::hypot(x, y) <= radius_)
          s.points.push_back({static_cast<float>(x), static_cast<float>(y), -1.8f, 0.5f, 0, 0});
    return s;
  }

 private:
  std::size_t n_;
  double radius_;
};

Trajectory atCentre(std::size_t n) {
  Trajectory t;
  for (std::size_t i = 0; i < n; ++i) {
    Pose3 T = Pose3::Identity();
    T.translation() = Vec3(500, 500, 1.8);  // the plus junction, sensor 1.8 m up
    t.push_back({0.1 * static_cast<double>(i), T});
  }
  return t;
}

TEST(MapCompleteness, UnknownAndFrontierShareNearTheStreets) {
  const RoadGraph g = RoadGraph::fromSumoNet(
      SumoNet::read(std::string(SLAMROUTE_SOURCE_DIR) + "/networks/test/plus.net.xml"));
  GridConfig gc;
  gc.max_range_m = 1e4;
  // seen: a 20 m disc around the junction
  const OccupancyGrid part = occupancyFromScans(GroundDiscScans(3, 20.0), atCentre(3), g, gc, 0.0);
  const std::vector<bool> mask = streetMask(part, g, 30.0);
  const MapCompleteness m = mapCompleteness(part, mask, GpConfig{});
  ASSERT_GT(m.cells, 0u);
  const double disc_cells = M_PI * 20.0 * 20.0 / (gc.cell_m * gc.cell_m);
  EXPECT_NEAR(1.0 - m.unknown_share, disc_cells / static_cast<double>(m.cells),
              0.1 * disc_cells / m.cells);
  EXPECT_GT(m.frontier_share, 0.0);
  EXPECT_GT(m.mean_frontier_probability, 0.0);
  // seen everywhere: nothing unknown, no frontier
  const OccupancyGrid all = occupancyFromScans(GroundDiscScans(1, 400.0), atCentre(1), g, gc, 0.0);
  const MapCompleteness full = mapCompleteness(all, streetMask(all, g, 30.0), GpConfig{});
  EXPECT_EQ(full.unknown_share, 0.0);
  EXPECT_EQ(full.frontier_share, 0.0);
  writeFrontierProbabilityPng(test::testTmp() / "frontier.png", part, mask, GpConfig{});
  EXPECT_GT(std::filesystem::file_size(test::testTmp() / "frontier.png"), 100u);
  // poses at times no scan has: nothing to map
  Trajectory late = atCentre(2);
  for (auto& p : late) p.t += 100.0;
  EXPECT_THROW(occupancyFromScans(GroundDiscScans(2, 5.0), late, g, gc, 0.0),
               std::invalid_argument);
}

}  // namespace
}  // namespace slamroute::explore
