// Feature registration and the k-d tree under it, on synthetic feature clouds with known answers.
#include <gtest/gtest.h>

#include <algorithm>
#include <numbers>
#include <random>

#include "slamroute/evaluate/Registration.hpp"

namespace slamroute::evaluate {
namespace {

TEST(KdTree, NearestNeighboursEqualABruteForceSearch) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-20.0f, 20.0f);
  Cloud pts(2000);
  for (auto& p : pts) p = Eigen::Vector3f(u(rng), u(rng), 0.1f * u(rng));
  KdTree tree;
  tree.build(pts);
  std::vector<int> idx;
  std::vector<float> d2;
  for (int q = 0; q < 50; ++q) {
    const Eigen::Vector3f query(u(rng), u(rng), 0.0f);
    ASSERT_EQ(tree.knn(query, 5, idx, d2), 5);
    std::vector<float> all;
    for (const auto& p : pts) all.push_back((p - query).squaredNorm());
    std::sort(all.begin(), all.end());
    for (int i = 0; i < 5; ++i) {
      EXPECT_FLOAT_EQ(d2[static_cast<std::size_t>(i)], all[static_cast<std::size_t>(i)]);
      EXPECT_FLOAT_EQ((pts[static_cast<std::size_t>(idx[static_cast<std::size_t>(i)])] - query).squaredNorm(),
                      all[static_cast<std::size_t>(i)]);
    }
  }
  KdTree empty;
  empty.build({});
  EXPECT_EQ(empty.knn(Eigen::Vector3f::Zero(), 5, idx, d2), 0);
  EXPECT_EQ(tree.knn(Eigen::Vector3f::Zero(), 5000, idx, d2), 2000);  // asks for more than there are
}

/// A street corner as features: vertical edges (building corners, poles) and planar points on
/// the ground and two facades at right angles.
FeatureMap corner(Cloud& edges, Cloud& planes) {
  for (int k = 0; k < 12; ++k)
    for (double z = 0.2; z < 6.0; z += 0.2)
      edges.emplace_back(static_cast<float>(-15.0 + 3.0 * k), static_cast<float>(k % 2 ? 8.0 : -8.0),
                         static_cast<float>(z));
  for (double x = -20; x <= 20; x += 0.4)
    for (double y = -8; y <= 8; y += 0.4) planes.emplace_back(static_cast<float>(x), static_cast<float>(y), 0.0f);
  for (double x = -20; x <= 20; x += 0.4)
    for (double z = 0.2; z < 8; z += 0.4) planes.emplace_back(static_cast<float>(x), 9.0f, static_cast<float>(z));
  for (double y = -8; y <= 8; y += 0.4)
    for (double z = 0.2; z < 8; z += 0.4) planes.emplace_back(21.0f, static_cast<float>(y), static_cast<float>(z));
  FeatureMap map;
  map.build(edges, planes);
  return map;
}

Cloud moved(const Cloud& c, const Pose3& T) {
  Cloud out;
  for (const auto& p : c) out.push_back((T * p.cast<double>()).cast<float>());
  return out;
}

class AlignFeatures : public ::testing::TestWithParam<int> {};

TEST_P(AlignFeatures, RecoversKnownRigidMotion) {
  Cloud edges, planes;
  const FeatureMap map = corner(edges, planes);
  // The source is the map seen from a pose T_true; start the registration from identity.
  Pose3 T_true = Pose3::Identity();
  T_true.linear() = Eigen::AngleAxisd(3.0 * std::numbers::pi / 180.0, Vec3::UnitZ()).toRotationMatrix();
  T_true.translation() = Vec3(0.4, -0.25, 0.05);
  const Pose3 T_src = T_true.inverse();
  AlignOptions opt;
  opt.iterations = 30;
  opt.reassociate_every = GetParam();
  const AlignResult r = alignFeatures(map, moved(edges, T_src), moved(planes, T_src), Pose3::Identity(), opt);
  const Pose3 err = T_true.inverse() * r.T_target_source;
  EXPECT_LT(err.translation().norm(), 0.01) << err.translation().transpose();
  EXPECT_LT(Eigen::AngleAxisd(err.rotation()).angle() * 180.0 / std::numbers::pi, 0.1);
  EXPECT_TRUE(r.converged);
  EXPECT_GT(r.edge_matches, 100);
  EXPECT_GT(r.plane_matches, 1000);
}

INSTANTIATE_TEST_SUITE_P(ReassociateEvery, AlignFeatures, ::testing::Values(1, 2, 3));

/// A street between two long walls (planes y = +-8) and the ground: nothing fixes x.
FeatureMap corridor(Cloud& planes) {
  for (double x = -30; x <= 30; x += 0.4)
    for (double y = -8; y <= 8; y += 0.4) planes.emplace_back(static_cast<float>(x), static_cast<float>(y), 0.0f);
  for (double x = -30; x <= 30; x += 0.4)
    for (double z = 0.2; z < 8; z += 0.4) {
      planes.emplace_back(static_cast<float>(x), 8.0f, static_cast<float>(z));
      planes.emplace_back(static_cast<float>(x), -8.0f, static_cast<float>(z));
    }
  FeatureMap map;
  map.build({}, planes);
  return map;
}

TEST(AlignFeaturesPrior, DecidesTheDirectionTheFeaturesLeaveOpen) {
  Cloud planes;
  const FeatureMap map = corridor(planes);
  // The source sees the corridor from (0, 0.3): the walls bring y back to 0.3; along the
  // corridor only the sampling pattern of the planes says anything.
  Pose3 T_true = Pose3::Identity();
  T_true.translation() = Vec3(0.0, 0.3, 0.0);
  const Cloud src = moved(planes, T_true.inverse());
  AlignOptions opt;
  opt.iterations = 20;
  Pose3 init = Pose3::Identity();
  init.translation() = Vec3(0.5, 0.0, 0.0);
  const AlignResult free = alignFeatures(map, {}, src, init, opt);
  EXPECT_NEAR(free.T_target_source.translation().y(), 0.3, 0.01);
  // A prior on x only at 0.7 (the odometry): x follows it, y still follows the walls.
  opt.prior = Pose3::Identity();
  opt.prior.translation() = Vec3(0.7, 0.0, 0.0);
  opt.prior_weight << 0, 0, 0, 1000, 0, 0;
  const AlignResult with = alignFeatures(map, {}, src, init, opt);
  EXPECT_NEAR(with.T_target_source.translation().x(), 0.7, 0.03);
  EXPECT_NEAR(with.T_target_source.translation().y(), 0.3, 0.01);
  EXPECT_GT(std::abs(free.T_target_source.translation().x() - 0.7), 0.3);
}

TEST(AlignFeaturesPrior, AWeakPriorDoesNotMoveAConstrainedResult) {
  Cloud edges, planes;
  const FeatureMap map = corner(edges, planes);
  Pose3 T_true = Pose3::Identity();
  T_true.translation() = Vec3(0.4, -0.25, 0.05);
  AlignOptions opt;
  opt.iterations = 30;
  opt.prior = Pose3::Identity();  // a prior 0.47 m off
  opt.prior_weight << 0, 0, 1, 1, 1, 0;
  const AlignResult r = alignFeatures(map, moved(edges, T_true.inverse()), moved(planes, T_true.inverse()),
                                      Pose3::Identity(), opt);
  EXPECT_LT((r.T_target_source.translation() - T_true.translation()).norm(), 0.01);
}

}  // namespace
}  // namespace slamroute::evaluate
