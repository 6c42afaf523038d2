// Feature registration on synthetic feature clouds with known answers.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include <algorithm>
#include <numbers>
#include <random>
#include <utility>

#include "SyntheticScene.hpp"
#include "slamroute/evaluate/Config.hpp"
#include "slamroute/evaluate/Registration.hpp"

namespace slamroute::evaluate {
namespace {

/// A street corner as features: vertical edges (building corners, poles) and planar points on
/// the ground and two facades at right angles.
FeatureMap corner(Cloud& edges, Cloud& planes) {
  for (int k = 0; k < 12; ++k)
    for (double z = 0.2; z < 6.0; z += 0.2)
      edges.emplace_back(static_cast<float>(-15.0 + 3.0 * k),
                         static_cast<float>(k % 2 ? 8.0 : -8.0), static_cast<float>(z));
  for (double x = -20; x <= 20; x += 0.4)
    for (double y = -8; y <= 8; y += 0.4)
      planes.emplace_back(static_cast<float>(x), static_cast<float>(y), 0.0f);
  for (double x = -20; x <= 20; x += 0.4)
    for (double z = 0.2; z < 8; z += 0.4)
      planes.emplace_back(static_cast<float>(x), 9.0f, static_cast<float>(z));
  for (double y = -8; y <= 8; y += 0.4)
    for (double z = 0.2; z < 8; z += 0.4)
      planes.emplace_back(21.0f, static_cast<float>(y), static_cast<float>(z));
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
  T_true.linear() =
      Eigen::AngleAxisd(3.0 * std::numbers::pi / 180.0, Vec3::UnitZ()).toRotationMatrix();
  T_true.translation() = Vec3(0.4, -0.25, 0.05);
  const Pose3 T_src = T_true.inverse();
  AlignOptions opt;
  opt.iterations = 30;
  opt.reassociate_every = GetParam();
  const AlignResult r =
      alignFeatures(map, moved(edges, T_src), moved(planes, T_src), Pose3::Identity(), opt);
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
    for (double y = -8; y <= 8; y += 0.4)
      planes.emplace_back(static_cast<float>(x), static_cast<float>(y), 0.0f);
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
  const AlignResult r = alignFeatures(map, moved(edges, T_true.inverse()),
                                      moved(planes, T_true.inverse()), Pose3::Identity(), opt);
  EXPECT_LT((r.T_target_source.translation() - T_true.translation()).norm(), 0.01);
}

TEST(AlignFeaturesPrior, AFadedPriorActsWhereTheFeaturesAreWeakOnly) {
  AlignOptions opt;
  opt.iterations = 30;
  opt.prior_weight << 0, 0, 0, 1000, 0, 0;
  opt.prior_fade_info << 0, 0, 0, 0.05, 0, 0;
  // The corridor says nothing along x: the faded prior holds x at the odometry's 0.7.
  Cloud corridor_planes;
  const FeatureMap open = corridor(corridor_planes);
  opt.prior.translation() = Vec3(0.7, 0.0, 0.0);
  Pose3 T_true = Pose3::Identity();
  T_true.translation() = Vec3(0.0, 0.3, 0.0);
  const AlignResult along =
      alignFeatures(open, {}, moved(corridor_planes, T_true.inverse()), Pose3::Identity(), opt);
  EXPECT_NEAR(along.T_target_source.translation().x(), 0.7, 0.03);
  // The corner holds x itself: the same prior, 0.3 m off, no longer moves the result.
  Cloud edges, planes;
  const FeatureMap held = corner(edges, planes);
  T_true.translation() = Vec3(0.4, -0.25, 0.05);
  opt.prior.translation() = Vec3(0.7, -0.25, 0.05);
  const AlignResult r = alignFeatures(held, moved(edges, T_true.inverse()),
                                      moved(planes, T_true.inverse()), Pose3::Identity(), opt);
  EXPECT_LT((r.T_target_source.translation() - T_true.translation()).norm(), 0.01);
  opt.prior_fade_info.setZero();  // unfaded, the same weight pulls x towards the prior
  const AlignResult pulled = alignFeatures(held, moved(edges, T_true.inverse()),
                                           moved(planes, T_true.inverse()), Pose3::Identity(), opt);
  EXPECT_GT(pulled.T_target_source.translation().x() - T_true.translation().x(), 0.05);
}

/// A round plaza: the ground and a circular wall of radius 12 m around the origin. Turning about
/// the centre moves every point along its own surface, so nothing fixes the yaw.
FeatureMap plaza(Cloud& planes) {
  for (double x = -11; x <= 11; x += 0.4)
    for (double y = -11; y <= 11; y += 0.4)
      if (x * x + y * y < 121)
        planes.emplace_back(static_cast<float>(x), static_cast<float>(y), 0.0f);
  for (int k = 0; k < 360; ++k)
    for (double z = 0.2; z < 6; z += 0.4) {
      const double a = k * std::numbers::pi / 180.0;
      planes.emplace_back(static_cast<float>(12 * std::cos(a)),
                          static_cast<float>(12 * std::sin(a)), static_cast<float>(z));
    }
  FeatureMap map;
  map.build({}, planes);
  return map;
}

Pose3 turned(double yaw_deg, const Vec3& t) {
  Pose3 T = Pose3::Identity();
  T.linear() =
      Eigen::AngleAxisd(yaw_deg * std::numbers::pi / 180.0, Vec3::UnitZ()).toRotationMatrix();
  T.translation() = t;
  return T;
}

double yawDeg(const Pose3& T) {
  return std::atan2(T.linear()(1, 0), T.linear()(0, 0)) * 180.0 / std::numbers::pi;
}

TEST(AlignFeaturesPrior, AFadedYawPriorHoldsTheTurnWhereTheFeaturesLeaveItOpen) {
  // The LiDAR-only default: the constant velocity's yaw, 0.1 deg per 0.1 s against 0.05 m.
  const OdometryConfig dflt;
  AlignOptions opt;
  opt.iterations = 30;
  opt.prior_weight(2) = std::pow(dflt.prior_registration_sigma_m /
                                     (dflt.velocity_prior_yaw_sigma_deg * std::numbers::pi / 180.0),
                                 2);
  opt.prior_fade_info(2) = dflt.velocity_prior_yaw_fade_info;
  // In the plaza the prior decides the yaw (1 deg), the wall still the position.
  Cloud plaza_planes;
  const FeatureMap plaza_map = plaza(plaza_planes);
  const Pose3 T_true = turned(3.0, Vec3(0.3, -0.2, 0.0));
  opt.prior = turned(1.0, T_true.translation());
  const AlignResult open =
      alignFeatures(plaza_map, {}, moved(plaza_planes, T_true.inverse()), Pose3::Identity(), opt);
  EXPECT_NEAR(yawDeg(open.T_target_source), 1.0, 0.05);
  EXPECT_LT((open.T_target_source.translation() - T_true.translation()).norm(), 0.02);
  // At the corner the facades hold the yaw: the same prior, 2 deg off, fades out (the result of
  // no prior at all); unfaded it would pull the yaw towards 1 deg.
  Cloud edges, planes;
  const FeatureMap held = corner(edges, planes);
  const Cloud src_edges = moved(edges, T_true.inverse()),
              src_planes = moved(planes, T_true.inverse());
  AlignOptions none = opt;
  none.prior_weight.setZero();
  const Pose3 free =
      alignFeatures(held, src_edges, src_planes, Pose3::Identity(), none).T_target_source;
  const Pose3 faded =
      alignFeatures(held, src_edges, src_planes, Pose3::Identity(), opt).T_target_source;
  EXPECT_NEAR(yawDeg(free), 3.0, 0.01);
  EXPECT_NEAR(yawDeg(faded), yawDeg(free), 1e-6);
  opt.prior_fade_info.setZero();
  const Pose3 pulled =
      alignFeatures(held, src_edges, src_planes, Pose3::Identity(), opt).T_target_source;
  EXPECT_LT(yawDeg(pulled), yawDeg(free) - 0.002);
}

/// The corridor with vertical lines (poles) every 7 m on both sides, 1 m in front of the walls.
FeatureMap corridorWithPoles(Cloud& edges, Cloud& planes) {
  for (double x = -28; x <= 28; x += 7)
    for (double z = 0.2; z < 4.0; z += 0.2)
      for (const double y : {-7.0, 7.0})
        edges.emplace_back(static_cast<float>(x + (y > 0 ? 3.0 : 0.0)), static_cast<float>(y),
                           static_cast<float>(z));
  corridor(planes);  // the walls and the ground
  FeatureMap map;
  map.build(edges, planes);
  return map;
}

class EdgeWeight : public ::testing::TestWithParam<double> {};

TEST_P(EdgeWeight, EdgesAloneHoldWhatThePlanesLeaveOpen) {
  // Along the corridor only the poles say where the scan is (and, weakly, the planes' sampling
  // pattern: at a hundredth of their weight the edges lose to it).
  Cloud edges, planes;
  const FeatureMap map = corridorWithPoles(edges, planes);
  Pose3 T_true = Pose3::Identity();
  T_true.translation() = Vec3(0.4, 0.3, 0.0);
  AlignOptions opt;
  opt.iterations = 30;
  opt.edge_weight = GetParam();
  const AlignResult r = alignFeatures(map, moved(edges, T_true.inverse()),
                                      moved(planes, T_true.inverse()), Pose3::Identity(), opt);
  EXPECT_LT((r.T_target_source.translation() - T_true.translation()).norm(), 0.01)
      << r.T_target_source.translation().transpose();
}

INSTANTIATE_TEST_SUITE_P(Weights, EdgeWeight, ::testing::Values(1.0, 0.3, 0.1));

TEST(EdgeWeight, ALowWeightLetsThePlanesOverruleEdgesThatLag) {
  // The corner, with the scan's edges 10 cm further along x than the map's (silhouettes of
  // round things seen from further on): the planes, x held by the facade at x = 21, say 0.4.
  Cloud edges, planes;
  const FeatureMap map = corner(edges, planes);
  Pose3 T_true = Pose3::Identity();
  T_true.translation() = Vec3(0.4, -0.25, 0.05);
  Pose3 lag = Pose3::Identity();
  lag.translation() = Vec3(0.1, 0.0, 0.0);
  const Cloud src_edges = moved(edges, T_true.inverse() * lag);
  const Cloud src_planes = moved(planes, T_true.inverse());
  const auto xError = [&](double weight) {
    AlignOptions opt;
    opt.iterations = 30;
    opt.edge_weight = weight;
    const AlignResult r = alignFeatures(map, src_edges, src_planes, Pose3::Identity(), opt);
    return std::abs(r.T_target_source.translation().x() - T_true.translation().x());
  };
  const double full = xError(1.0), low = xError(0.1);
  EXPECT_GT(full, 0.01);
  EXPECT_LT(low, 0.3 * full) << full << " " << low;
}

/// A street 16 m wide between two facades along x (-60..60 m), with the ground, and 2 m wide
/// pillars standing 1 m out of each facade at the given x positions; 0.4 m point spacing.
Cloud streetWithPillars(const std::vector<double>& pillars_x) {
  Cloud c;
  const auto add = [&](double x, double y, double z) {
    c.emplace_back(static_cast<float>(x), static_cast<float>(y), static_cast<float>(z));
  };
  for (double x = -60; x <= 60; x += 0.4) {
    for (double y = -8; y <= 8; y += 0.4) add(x, y, 0.0);
    for (double z = 0.2; z < 6; z += 0.4) add(x, 8.0, z), add(x, -8.0, z);
  }
  for (const double px : pillars_x)
    for (double z = 0.2; z < 6; z += 0.4)
      for (double side : {1.0, -1.0}) {
        for (double x = px - 1.0; x <= px + 1.0; x += 0.4) add(x, side * 7.0, z);  // front face
        for (double y = 7.0; y < 8.0; y += 0.4)
          add(px - 1.0, side * y, z), add(px + 1.0, side * y, z);
      }
  return c;
}

/// What a keyframe at the origin sees of it: the points within 25 m.
Cloud near(const Cloud& c) {
  Cloud out;
  for (const auto& p : c)
    if (p.head<2>().norm() < 25.0f) out.push_back(p);
  return out;
}

IcpAmbiguity alongTheStreet() {
  IcpAmbiguity amb;
  amb.along_m = {3, 6, 9};
  amb.across_m = {3};
  amb.rival_share = 0.98;
  return amb;
}

TEST(IcpAmbiguity, AMatchStuckOnTheWrongPillarsHasABetterOneWhereItBelongs) {
  // A drifted estimate 6 m along the street: walls and ground match anywhere, so ICP stays
  // there and the match even passes the fitness test (a false loop closure).
  const Cloud world = streetWithPillars({-47, -31, -26, -12, -4, 5, 9, 21, 32, 35, 50});
  const IcpTarget target(world);
  const Cloud source = near(world);
  const IcpAmbiguity amb = alongTheStreet();
  const IcpResult wrong =
      target.align(source, test::poseXYZYaw(6.0, 0.0, 0.0, 0.0), amb.iterations, amb.max_corr_m);
  ASSERT_TRUE(amb.accept(wrong));
  ASSERT_GT(wrong.T_target_source.translation().norm(), 5.0);
  // Started 6 m back, ICP finds the true pose, which fits better.
  const IcpRival rival = strongestRival(target, source, wrong, amb);
  EXPECT_TRUE(rival.better);
  EXPECT_NEAR(rival.apart_m, wrong.T_target_source.translation().norm(), 0.1);
  EXPECT_TRUE(ambiguousMatch(rival, amb));
  // That rival has none of its own that fits as well: it is where the keyframe is.
  const std::optional<IcpResult> unique = uniqueMatch(target, source, wrong, amb);
  ASSERT_TRUE(unique.has_value());
  EXPECT_LT(unique->T_target_source.translation().norm(), 0.05);
}

/// ICP from the true pose of what a keyframe at the origin sees of a street, and the strongest
/// rival of that match.
std::pair<IcpResult, IcpRival> trueMatchOn(const std::vector<double>& pillars_x) {
  const Cloud world = streetWithPillars(pillars_x);
  const IcpTarget target(world);
  const Cloud source = near(world);
  const IcpAmbiguity amb = alongTheStreet();
  const IcpResult r = target.align(source, Pose3::Identity(), amb.iterations, amb.max_corr_m);
  return {r, strongestRival(target, source, r, amb)};
}

TEST(IcpAmbiguity, TheTrueMatchAmongIrregularPillarsIsUnique) {
  const auto [match, rival] = trueMatchOn({-47, -31, -26, -12, -4, 5, 9, 21, 32, 35, 50});
  const IcpAmbiguity amb = alongTheStreet();
  ASSERT_TRUE(amb.accept(match));
  EXPECT_LT(match.T_target_source.translation().norm(), 0.05);
  EXPECT_FALSE(rival.better);
  EXPECT_LT(rival.share, amb.rival_share);
  EXPECT_FALSE(ambiguousMatch(rival, amb));
}

/// The cloud with every coordinate moved by up to +-amp_m (a fixed pseudo-random sequence): the
/// noise of a real scan, so that no fit is exact.
Cloud jittered(const Cloud& c, float amp_m) {
  std::uint32_t state = 12345u;
  const auto next = [&state, amp_m] {
    state = state * 1664525u + 1013904223u;
    return amp_m * (2.0f * static_cast<float>(state >> 8) / static_cast<float>(1u << 24) - 1.0f);
  };
  Cloud out = c;
  for (auto& p : out) p += Eigen::Vector3f(next(), next(), next());
  return out;
}

TEST(IcpAmbiguity, ABareCorridorHasARivalAlongIt) {
  // Walls and ground only (a bridge between uniform parapets): starts along the street end
  // there, so the position along it is not measured.
  const Cloud world = streetWithPillars({});
  const IcpTarget target(world);
  const Cloud source = jittered(near(world), 0.05f);
  const IcpAmbiguity amb = alongTheStreet();
  const IcpResult r = target.align(source, Pose3::Identity(), amb.iterations, amb.max_corr_m);
  ASSERT_TRUE(amb.accept(r));
  const IcpRival rival = strongestRival(target, source, r, amb);
  EXPECT_GT(rival.apart_m, amb.separation_m);
  EXPECT_TRUE(ambiguousMatch(rival, amb)) << "share " << rival.share;
}

TEST(IcpAmbiguity, AUniqueTrueMatchIsKeptAndABareCorridorHasNone) {
  const std::vector<double> irregular{-47, -31, -26, -12, -4, 5, 9, 21, 32, 35, 50};
  const Cloud world = streetWithPillars(irregular);
  const IcpTarget target(world);
  const Cloud source = near(world);
  const IcpAmbiguity amb = alongTheStreet();
  const IcpResult match = target.align(source, Pose3::Identity(), amb.iterations, amb.max_corr_m);
  const std::optional<IcpResult> unique = uniqueMatch(target, source, match, amb);
  ASSERT_TRUE(unique.has_value());
  EXPECT_TRUE(unique->T_target_source.isApprox(match.T_target_source));

  const Cloud bare = streetWithPillars({});
  const IcpTarget corridor(bare);
  const Cloud seen = jittered(near(bare), 0.05f);
  const IcpResult r = corridor.align(seen, Pose3::Identity(), amb.iterations, amb.max_corr_m);
  ASSERT_TRUE(amb.accept(r));
  EXPECT_FALSE(uniqueMatch(corridor, seen, r, amb).has_value());
}

TEST(IcpAmbiguity, ARivalThatFitsAsWellButNoBetterCountsFromTheShareOn) {
  const IcpRival as_good{6.0, 0.99, false};
  IcpAmbiguity amb;
  amb.rival_share = 0.98;
  EXPECT_TRUE(ambiguousMatch(as_good, amb));
  amb.rival_share = 1.0;  // only better fits
  EXPECT_FALSE(ambiguousMatch(as_good, amb));
  EXPECT_TRUE(ambiguousMatch(IcpRival{6.0, 0.5, true}, amb));
  EXPECT_FALSE(ambiguousMatch(IcpRival{}, amb));  // no rival at all
}

TEST(IcpAmbiguity, EqualPillarsEveryFewMetresFitNoBetterElsewhere) {
  std::vector<double> periodic;
  for (double x = -56; x <= 56; x += 8) periodic.push_back(x);
  const auto [match, rival] = trueMatchOn(periodic);
  ASSERT_TRUE(alongTheStreet().accept(match));
  EXPECT_LT(match.T_target_source.translation().norm(), 0.05);
  EXPECT_FALSE(rival.better);
}

TEST(IcpTarget, TranslationInformationShowsWhatAStreetLeavesOpen) {
  // Bare facades and ground: nothing faces along the street (x), everything else does; pillars
  // put their sides across it.
  const Cloud bare = streetWithPillars({});
  const Mat3 open = IcpTarget(bare).translationInformation(near(bare), Pose3::Identity(), 0.7);
  EXPECT_LT(open(0, 0), 1e-3);
  EXPECT_GT(open(1, 1), 0.2);
  EXPECT_GT(open(2, 2), 0.4);
  EXPECT_NEAR(open.trace(), 1.0, 1e-6);  // unit normals: a mean of n n^T
  const Cloud pillars = streetWithPillars({-20, -12, -4, 5, 9, 21});
  const Mat3 held =
      IcpTarget(pillars).translationInformation(near(pillars), Pose3::Identity(), 0.7);
  EXPECT_GT(held(0, 0), 0.02);
}

}  // namespace
}  // namespace slamroute::evaluate
