#include <gtest/gtest.h>

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

}  // namespace
}  // namespace slamroute::evaluate
