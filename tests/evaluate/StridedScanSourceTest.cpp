#include <gtest/gtest.h>

#include "slamroute/evaluate/Slam.hpp"
#include "slamroute/evaluate/StridedScanSource.hpp"

namespace slamroute::evaluate {
namespace {

class Counting : public ScanSource {
 public:
  std::size_t size() const override { return 7; }
  double time(std::size_t i) const override { return 0.1 * static_cast<double>(i); }
  Scan scan(std::size_t i) const override {
    Scan s;
    s.points.resize(i);  // scan i has i points
    return s;
  }
  LidarSpec spec() const override { return lidarPreset("vlp16"); }
};

TEST(StridedScanSource, EveryNthScan) {
  const Counting base;
  const StridedScanSource s3(base, 3);
  ASSERT_EQ(s3.size(), 3u);  // scans 0, 3, 6
  EXPECT_DOUBLE_EQ(s3.time(2), 0.6);
  EXPECT_EQ(s3.scan(1).points.size(), 3u);
  EXPECT_EQ(s3.spec().channels, 16);
  EXPECT_EQ(StridedScanSource(base, 1).size(), 7u);
  EXPECT_THROW(StridedScanSource(base, 0), std::invalid_argument);
}

TEST(StridedScanSource, TimeWindow) {
  const Counting base;                             // times 0.0 ... 0.6
  const StridedScanSource w(base, 2, 0.15, 0.55);  // scans 2..5, every second: 2, 4
  ASSERT_EQ(w.size(), 2u);
  EXPECT_DOUBLE_EQ(w.time(0), 0.2);
  EXPECT_EQ(w.scan(1).points.size(), 4u);
  EXPECT_EQ(StridedScanSource(base, 1, 0.3).size(), 4u);  // to the end: 3..6
  EXPECT_EQ(StridedScanSource(base, 1, 1.0).size(), 0u);  // window after the drive
}

// runSlam's scan order: a dense stretch (every scan) that ends on an odd scan returns to the even
// grid, so two runs that densified differently feed the same scans afterwards.
TEST(StridedScanSource, StridedScansReturnToTheGridAfterADenseStretch) {
  EXPECT_EQ(nextScanIndex(4, 2, false), 6u);
  EXPECT_EQ(nextScanIndex(5, 2, false), 6u);  // after a dense stretch ending on 5: 6, not 7
  EXPECT_EQ(nextScanIndex(5, 2, true), 6u);
  EXPECT_EQ(nextScanIndex(6, 2, true), 7u);
  EXPECT_EQ(nextScanIndex(7, 3, false), 9u);
  EXPECT_EQ(nextScanIndex(7, 1, false), 8u);
  // Two runs over 0..20, one dense at scan 6 (a failure), the other never: the same from 10 on.
  std::vector<std::size_t> a, b;
  for (std::size_t i = 0; i <= 20; i = nextScanIndex(i, 2, i >= 5 && i < 7)) a.push_back(i);
  for (std::size_t i = 0; i <= 20; i = nextScanIndex(i, 2, false)) b.push_back(i);
  EXPECT_EQ(a, (std::vector<std::size_t>{0, 2, 4, 6, 7, 8, 10, 12, 14, 16, 18, 20}));
  EXPECT_EQ(std::vector<std::size_t>(a.end() - 6, a.end()),
            std::vector<std::size_t>(b.end() - 6, b.end()));
}

}  // namespace
}  // namespace slamroute::evaluate
