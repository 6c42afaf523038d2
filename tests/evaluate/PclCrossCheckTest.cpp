// PCL as an independent check of two of our own parts: map.pcd must load in PCL's reader (the one
// pcl_viewer and CloudCompare's PCL plugin use) point for point, and our point-to-plane ICP must
// find the same motion as PCL's generalized ICP on the same pair of scans.
#include <gtest/gtest.h>
#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>

#include <filesystem>
#include <numbers>
#include <optional>

#include "PclGicp.hpp"
#include "SyntheticScene.hpp"
#include "TestTmp.hpp"
#include "slamroute/evaluate/Output.hpp"
#include "slamroute/evaluate/Registration.hpp"

namespace slamroute::evaluate {
namespace {
namespace fs = std::filesystem;

pcl::PointCloud<pcl::PointXYZ> loadWithPcl(const fs::path& file) {
  pcl::PointCloud<pcl::PointXYZ> cloud;
  if (pcl::io::loadPCDFile(file.string(), cloud) != 0) ADD_FAILURE() << "PCL cannot read " << file;
  return cloud;
}

void expectSamePoints(const pcl::PointCloud<pcl::PointXYZ>& read, const Cloud& written) {
  ASSERT_EQ(read.size(), written.size());
  for (std::size_t i = 0; i < written.size(); ++i) {
    EXPECT_EQ(read[i].x, written[i].x()) << i;
    EXPECT_EQ(read[i].y, written[i].y()) << i;
    EXPECT_EQ(read[i].z, written[i].z()) << i;
  }
}

TEST(PclCrossCheck, PclReadsMapPcdPointForPoint) {
  const fs::path dir = slamroute::test::testTmp() / "pcl_cross_check";
  fs::create_directories(dir);
  Cloud first, second;
  for (int i = 0; i < 500; ++i) {
    first.emplace_back(0.25f * i, -1.5f * i, 1e-3f * i);
    second.emplace_back(-7.0f + i, 3.0e4f, -0.125f * i);
  }
  writePcd(dir / "whole.pcd", first);
  expectSamePoints(loadWithPcl(dir / "whole.pcd"), first);
  // The SLAM's map comes tile by tile through PcdWriter.
  PcdWriter parts(dir / "parts.pcd");
  parts.add(first);
  parts.add(second);
  parts.commit();
  Cloud both = first;
  both.insert(both.end(), second.begin(), second.end());
  expectSamePoints(loadWithPcl(dir / "parts.pcd"), both);
}

TEST(PclCrossCheck, IcpFindsTheMotionPclGeneralizedIcpFinds) {
  // Two scans of a street crossing 1.2 m and 4 degrees apart, both methods started at identity.
  const LidarSpec spec = test::coarseLidar(16);
  const test::Scene scene = test::cityScene(80.0);
  const Pose3 T_world_target = test::poseXYZYaw(0.0, 0.0, 1.8, 0.0);
  const Pose3 T_world_source = test::poseXYZYaw(1.0, 0.6, 1.8, 4.0 * std::numbers::pi / 180.0);
  const Cloud target = test::cloudOf(test::scanScene(scene, T_world_target, spec));
  const Cloud source = test::cloudOf(test::scanScene(scene, T_world_source, spec));
  const Pose3 truth = T_world_target.inverse() * T_world_source;

  const IcpResult ours = IcpTarget(target).align(source, Pose3::Identity(), 30, 2.0);
  const std::optional<Pose3> gicp = test::pclGicp(target, source, 2.0, 30);
  ASSERT_TRUE(gicp.has_value());
  const Pose3 theirs = *gicp;

  for (const Pose3& found : {ours.T_target_source, theirs}) {
    const Pose3 err = truth.inverse() * found;
    EXPECT_LT(err.translation().norm(), 0.05) << err.translation().transpose();
    EXPECT_LT(Eigen::AngleAxisd(err.rotation()).angle(), 0.2 * std::numbers::pi / 180.0);
  }
  EXPECT_LT((ours.T_target_source.translation() - theirs.translation()).norm(), 0.05);
}

}  // namespace
}  // namespace slamroute::evaluate
