// Seeded K-means: separated blobs are recovered with their means; same seed, same result.
#include <gtest/gtest.h>

#include <set>
#include <stdexcept>

#include "slamroute/core/KMeans.hpp"

namespace slamroute {
namespace {

KMeansOptions seeded(std::uint64_t seed) {
  KMeansOptions o;
  o.seed = seed;
  return o;
}

/// Three square blobs of 9 points (3 x 3, spacing 1 m) centred on (0,0), (100,0), (0,100).
std::vector<Point2> threeBlobs() {
  std::vector<Point2> pts;
  for (const Point2& c : {Point2(0, 0), Point2(100, 0), Point2(0, 100)})
    for (int i = -1; i <= 1; ++i)
      for (int j = -1; j <= 1; ++j) pts.push_back(c + Point2(i, j));
  return pts;
}

TEST(KMeans, RecoversSeparatedBlobsWithTheirMeansAndInertia) {
  const std::vector<Point2> pts = threeBlobs();
  for (std::uint64_t seed : {1u, 2u, 7u, 42u}) {
    const KMeansResult r = kMeans(pts, 3, seeded(seed));
    std::set<int> labels;
    for (int blob = 0; blob < 3; ++blob) {
      const int l = r.label[blob * 9];
      labels.insert(l);
      for (int i = 0; i < 9; ++i) EXPECT_EQ(r.label[blob * 9 + i], l);
      const Point2 expected = pts[blob * 9 + 4];  // the blob's middle point is its mean
      EXPECT_NEAR((r.centre[l] - expected).norm(), 0.0, 1e-12);
    }
    EXPECT_EQ(labels.size(), 3u);
    EXPECT_NEAR(r.inertia, 3 * 12.0, 1e-9);  // per blob: 4 points at 1 m^2, 4 at 2 m^2
  }
}

TEST(KMeans, SameSeedSameResult) {
  std::vector<Point2> pts;
  for (int i = 0; i < 200; ++i) pts.emplace_back((i * 37) % 101, (i * 53) % 89);
  const KMeansResult a = kMeans(pts, 5, seeded(9)), b = kMeans(pts, 5, seeded(9));
  EXPECT_EQ(a.label, b.label);
  EXPECT_EQ(a.inertia, b.inertia);
  for (int c = 0; c < 5; ++c) EXPECT_EQ(a.centre[c], b.centre[c]);
}

TEST(KMeans, WeightsPullTheCentre) {
  // One cluster: the centre is the weighted mean, (0*1 + 10*3) / 4 = 7.5.
  const KMeansResult r = kMeans({Point2(0, 0), Point2(10, 0)}, 1, {.weight = {1.0, 3.0}});
  EXPECT_NEAR(r.centre[0].x(), 7.5, 1e-12);
}

TEST(KMeans, EveryClusterKeepsAPointEvenWithDuplicates) {
  const std::vector<Point2> pts(6, Point2(1, 1));
  const KMeansResult r = kMeans(pts, 3);
  std::set<int> used(r.label.begin(), r.label.end());
  EXPECT_EQ(used.size(), 3u);
}

TEST(KMeans, RejectsBadArguments) {
  const std::vector<Point2> pts = threeBlobs();
  EXPECT_THROW(kMeans(pts, 0), std::invalid_argument);
  EXPECT_THROW(kMeans(pts, 28), std::invalid_argument);
  EXPECT_THROW(kMeans(pts, 2, {.weight = {1.0}}), std::invalid_argument);
}

}  // namespace
}  // namespace slamroute
