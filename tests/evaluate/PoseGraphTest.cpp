// The pose graph with the IMU's pitch per node and its bias as an unknown (PitchFactors): a square
// lap driven by a front end that levelled with the biased IMU sinks by the bias per metre; the
// closure back at the start tells the graph the bias, and the corrected lap is level again.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "slamroute/evaluate/PoseGraph.hpp"

namespace slamroute::evaluate {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr int kSide = 50;      // keyframes per side of the square
constexpr double kStep = 2.0;  // metres between keyframes

constexpr int kLaps = 3;

/// True poses of kLaps laps of a 100 m square, level, 4 x kSide keyframes a lap, turning left at
/// the corners.
std::vector<Pose3> trueLaps() {
  std::vector<Pose3> poses;
  Vec3 p = Vec3::Zero();
  for (int k = 0; k < kLaps * 4 * kSide + 1; ++k) {
    Pose3 T = Pose3::Identity();
    T.linear() = Eigen::AngleAxisd((k / kSide) * std::numbers::pi / 2, Vec3::UnitZ()).matrix();
    T.translation() = p;
    poses.push_back(T);
    p += T.linear() * Vec3(kStep, 0, 0);
  }
  return poses;
}

struct Lap {
  std::vector<Pose3> truth, poses;
  std::vector<PoseGraphEdge> edges;
  PitchFactors pitch;
};

/// What a front end levelled with an IMU reading `b` nose-down too much builds: every keyframe
/// after the first pitched by b, the true body-frame steps chained on them (the lap sinks by
/// sin(b) per metre), odometry edges between consecutive keyframes, a true closure from every
/// corner of the later laps back to the first lap's, and the IMU's readings (truth + b + 0.1 deg
/// white noise).
Lap biasedLap(double b, unsigned seed) {
  Lap lap;
  lap.truth = trueLaps();
  Vec3 p = Vec3::Zero();
  for (std::size_t k = 0; k < lap.truth.size(); ++k) {
    Pose3 T = lap.truth[k];
    if (k > 0) T.linear() = T.linear() * Eigen::AngleAxisd(b, Vec3::UnitY()).matrix();
    T.translation() = p;
    lap.poses.push_back(T);
    if (k + 1 < lap.truth.size())
      p += T.linear() * (lap.truth[k].inverse() * lap.truth[k + 1]).translation();
  }
  for (std::size_t k = 0; k + 1 < lap.poses.size(); ++k) {
    PoseGraphEdge e;
    e.from = static_cast<int>(k);
    e.to = e.from + 1;
    e.T_from_to = lap.poses[k].inverse() * lap.poses[k + 1];
    // Steps known to 1 cm: looser ones would take up part of the sink as stretch instead of b.
    e.sigma_m = 0.01;
    lap.edges.push_back(e);
  }
  for (std::size_t k = 4 * kSide; k < lap.poses.size(); k += kSide) {
    PoseGraphEdge loop;
    loop.from = static_cast<int>(k);
    loop.to = static_cast<int>(k % (4 * kSide));
    loop.T_from_to = lap.truth[k].inverse() * lap.truth[k % (4 * kSide)];
    loop.sigma_m = 0.1;
    loop.sigma_rad = 0.01;
    lap.edges.push_back(loop);
  }
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, 0.1 * kDeg);
  for (std::size_t k = 0; k < lap.poses.size(); ++k)
    lap.pitch.imu_pitch_rad.push_back(b + noise(rng));
  lap.pitch.sigma_rad = 0.1 * kDeg;
  lap.pitch.bias_sigma_rad = 0.2 * kDeg;
  return lap;
}

double maxHeight(const std::vector<Pose3>& poses) {
  double m = 0.0;
  for (const auto& T : poses) m = std::max(m, std::abs(T.translation().z()));
  return m;
}

double meanPitchDeg(const std::vector<Pose3>& poses) {
  double sum = 0.0;
  for (const auto& T : poses) sum += std::asin(-T.linear()(2, 0)) / kDeg;
  return sum / static_cast<double>(poses.size());
}

class PoseGraphPitch : public ::testing::TestWithParam<double> {};

TEST_P(PoseGraphPitch, AClosureMeasuresTheBiasAndLevelsTheLap) {
  const double b = GetParam() * kDeg;
  Lap lap = biasedLap(b, 7);
  ASSERT_GT(maxHeight(lap.poses), 0.3);
  const PoseGraphResult r = optimizePoseGraph(lap.poses, lap.edges, 0, lap.pitch);
  EXPECT_NEAR(r.pitch_bias_rad / kDeg, GetParam(), 0.02);
  EXPECT_LT(maxHeight(lap.poses), 0.1);
  EXPECT_LT(std::abs(meanPitchDeg(lap.poses)), 0.1 * std::abs(GetParam()));
}

TEST_P(PoseGraphPitch, WithoutTheFactorsTheClosuresOnlySpreadTheHeightError) {
  const double b = GetParam() * kDeg;
  Lap alone = biasedLap(b, 7), tied = biasedLap(b, 7);
  const PoseGraphResult r = optimizePoseGraph(alone.poses, alone.edges, 0);
  optimizePoseGraph(tied.poses, tied.edges, 0, tied.pitch);
  EXPECT_EQ(r.pitch_bias_rad, 0.0);
  EXPECT_GT(maxHeight(alone.poses), 2.0 * maxHeight(tied.poses));  // sags between closures stay
}

TEST_P(PoseGraphPitch, ABiasHeldAtItsPriorIsNotEstimated) {
  const double b = GetParam() * kDeg;
  Lap lap = biasedLap(b, 7);
  lap.pitch.bias_prior_rad = b;  // known: the nodes follow the IMU less it
  lap.pitch.bias_sigma_rad = 0.0;
  const PoseGraphResult r = optimizePoseGraph(lap.poses, lap.edges, 0, lap.pitch);
  EXPECT_EQ(r.pitch_bias_rad, b);
  EXPECT_LT(maxHeight(lap.poses), 0.1);
}

INSTANTIATE_TEST_SUITE_P(Biases, PoseGraphPitch, ::testing::Values(0.1, -0.15, 0.3));

TEST(PoseGraph, OneIMUPitchPerNodeOrAnError) {
  Lap lap = biasedLap(0.1 * kDeg, 1);
  lap.pitch.imu_pitch_rad.pop_back();
  EXPECT_THROW(optimizePoseGraph(lap.poses, lap.edges, 0, lap.pitch), std::invalid_argument);
}

}  // namespace
}  // namespace slamroute::evaluate
