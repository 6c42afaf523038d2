// Stage 1 on synthetic scenes: projection, ground segmentation, clustering, features.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "SyntheticScene.hpp"
#include "slamroute/evaluate/Features.hpp"
#include "slamroute/evaluate/RangeImage.hpp"

namespace slamroute::evaluate {
namespace {

using test::Box;
using test::Scene;

/// The default LiDAR's scan of `scene` from 1.8 m above the origin, projected, its ground
/// segmented and the rest clustered.
RangeImage segmentedScan(const Scene& scene, const Config& cfg) {
  const LidarSpec spec;
  const Scan scan = test::scanScene(scene, test::poseXYZYaw(0, 0, 1.8, 0.0), spec);
  RangeImage img = projectScan(scan, spec, cfg);
  segmentGround(img, cfg);
  clusterRangeImage(img, cfg);
  return img;
}

TEST(RangeImage, PlanarGroundIsGround) {
  Scene scene;  // ground only
  const LidarSpec spec;
  const Scan scan = test::scanScene(scene, test::poseXYZYaw(0, 0, 1.8, 0.3), spec);
  Config cfg;
  RangeImage img = projectScan(scan, spec, cfg);
  ASSERT_GT(img.valid_points, 10000);
  EXPECT_EQ(img.valid_points, static_cast<int>(scan.points.size()));  // one return per cell
  segmentGround(img, cfg);
  int ground = 0;
  for (std::size_t i = 0; i < img.range.size(); ++i) ground += img.range[i] > 0 && img.ground[i];
  EXPECT_EQ(ground, img.valid_points);  // every return is on the plane
}

TEST(RangeImage, WallIsNotGroundAndFormsACluster) {
  Scene scene;
  scene.boxes.push_back({{8.0, -10.0, 0.0}, {9.0, 10.0, 8.0}});  // a wall 8 m ahead
  Config cfg;
  const RangeImage img = segmentedScan(scene, cfg);
  int wall = 0, wall_ground = 0, wall_clustered = 0;
  for (std::size_t i = 0; i < img.range.size(); ++i) {
    if (img.range[i] == 0 || img.point[i].z() < -1.0) continue;  // wall points are above z=-1
    ++wall;
    wall_ground += img.ground[i];
    wall_clustered += img.label[i] > 0;
  }
  ASSERT_GT(wall, 1000);
  EXPECT_LT(wall_ground, wall / 100);
  EXPECT_GT(wall_clustered, wall * 95 / 100);
  EXPECT_GE(img.clusters, 1);
  const FeatureSet f = extractFeatures(img, cfg);
  EXPECT_GT(f.flat.size(), 100u);  // from the ground
  EXPECT_GT(f.less_flat.size(), 100u);
  // sharp points exist at the wall's vertical edges (|y| close to 10)
  int at_edges = 0;
  for (const auto& p : f.sharp) at_edges += std::abs(std::abs(p.y()) - 10.0f) < 1.0f;
  EXPECT_GT(at_edges, 5);
}

TEST(RangeImage, SmallClustersAreOutliers) {
  Scene scene;
  scene.boxes.push_back({{20.0, 0.0, 1.0}, {20.05, 0.05, 1.05}});  // a 5 cm floating speck
  EXPECT_EQ(segmentedScan(scene, Config{}).clusters, 0);
}

TEST(RangeImage, EmptyAndNaNScansGiveEmptyImages) {
  const LidarSpec spec;
  Config cfg;
  Scan empty;
  EXPECT_EQ(projectScan(empty, spec, cfg).valid_points, 0);
  Scan nan;
  const float q = std::numeric_limits<float>::quiet_NaN();
  for (int i = 0; i < 1000; ++i) nan.points.push_back({q, q, q, 0.0f, i % 64});
  EXPECT_EQ(projectScan(nan, spec, cfg).valid_points, 0);
}

TEST(VoxelFilter, AveragesPerVoxel) {
  Cloud c = {{0.1f, 0.1f, 0.1f}, {0.3f, 0.3f, 0.3f}, {1.5f, 0.1f, 0.1f}};
  Cloud out = voxelFilter(c, 1.0);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_NEAR(out[0].x(), 0.2f, 1e-6);
  EXPECT_NEAR(out[1].x(), 1.5f, 1e-6);
}

}  // namespace
}  // namespace slamroute::evaluate
