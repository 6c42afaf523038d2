// Keyframe clouds in memory or in an unnamed file (evaluate/CloudStore.hpp), and the disk an
// evaluation needs for them and map.pcd.
#include <gtest/gtest.h>
#include "TestTmp.hpp"

#include <cstring>
#include <filesystem>
#include <random>

#include "slamroute/evaluate/CloudStore.hpp"
#include "slamroute/evaluate/Evaluate.hpp"

namespace slamroute::evaluate {
namespace {

Cloud randomCloud(std::mt19937& rng, std::size_t n) {
  std::uniform_real_distribution<float> u(-80.f, 80.f);
  Cloud c(n);
  for (auto& p : c) p = Eigen::Vector3f(u(rng), u(rng), u(rng));
  return c;
}

bool sameBits(const Cloud& a, const Cloud& b) {
  return a.size() == b.size() &&
         std::memcmp(a.data(), b.data(), a.size() * sizeof(Eigen::Vector3f)) == 0;
}

TEST(CloudStore, OnDiskGivesBackEveryCloudBitForBitAndLeavesNoFile) {
  const auto dir = test::testTmp();
  std::mt19937 rng(3);
  std::vector<Cloud> in;
  for (std::size_t n : {3000u, 0u, 1u, 12000u, 2500u}) in.push_back(randomCloud(rng, n));
  in[2][0] = Eigen::Vector3f(std::nanf(""), -0.f, 1e-40f);  // odd floats survive too
  CloudStore disk(dir), memory;
  EXPECT_TRUE(disk.onDisk());
  EXPECT_FALSE(memory.onDisk());
  for (std::size_t k = 0; k < in.size(); ++k) {
    EXPECT_EQ(disk.add(in[k]), static_cast<int>(k));
    EXPECT_EQ(memory.add(in[k]), static_cast<int>(k));
  }
  EXPECT_EQ(disk.size(), in.size());
  EXPECT_EQ(disk.bytesOnDisk(), (3000u + 1u + 12000u + 2500u) * 12u);
  EXPECT_EQ(memory.bytesOnDisk(), 0u);
  for (int k : {3, 0, 4, 1, 2, 3}) {  // any order, again and again
    EXPECT_TRUE(sameBits(disk.get(k), in[static_cast<std::size_t>(k)])) << k;
    EXPECT_TRUE(sameBits(memory.get(k), in[static_cast<std::size_t>(k)])) << k;
  }
  EXPECT_THROW(disk.get(5), std::out_of_range);
  EXPECT_THROW(memory.get(-1), std::out_of_range);
  // The file has no name: nothing is left in the folder, during the run or after it.
  EXPECT_TRUE(std::filesystem::is_empty(dir));
  memory.release(3);
  EXPECT_TRUE(memory.get(3).empty());
  disk.release(3);
  EXPECT_TRUE(sameBits(disk.get(3), in[3]));
}

TEST(CloudStore, AFolderThatDoesNotExistIsAnErrorNamingIt) {
  const auto dir = test::testTmp() / "missing";
  try {
    CloudStore s(dir);
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(dir.string()), std::string::npos) << e.what();
  }
}

TEST(EvaluationDisk, EstimateCoversTheMeasuredFiles) {
  Config cfg;  // keyframe clouds on disk
  // Default city, qlearning, 14.9 km: clouds 275 MB (evaluate's own figure) + map.pcd 86,468,300 B.
  EXPECT_GT(evaluationDiskGb(14.9, cfg), 0.275 + 0.0865);
  // Ingolstadt, postman, 74.5 km: 36,479 keyframes of ~47.4 kB + map.pcd 488,214,226 B.
  EXPECT_GT(evaluationDiskGb(74.5, cfg), 36479 * 47.4e-6 + 0.488);
  EXPECT_LT(evaluationDiskGb(74.5, cfg), 3.0);
  cfg.output.keyframe_clouds_on_disk = false;  // map.pcd and its tiles waiting for it (PcdWriter)
  EXPECT_GT(evaluationDiskGb(74.5, cfg), 2 * 0.488);
  EXPECT_LT(evaluationDiskGb(74.5, cfg), 1.3);
  EXPECT_EQ(evaluationDiskGb(-1.0, cfg), 0.0);
}

}  // namespace
}  // namespace slamroute::evaluate
