// The evaluation's plots read by a person: the estimate on top of the ground truth, coloured by
// its error; the error along the distance with gridlines at round values.
#include <gtest/gtest.h>
#include "TestTmp.hpp"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "slamroute/evaluate/Output.hpp"

namespace slamroute::evaluate {
namespace {
namespace fs = std::filesystem;

/// 500 m straight east; the estimate drifts 0 -> 2 m north, its error rising linearly.
TrajectoryMetrics straightDrive() {
  TrajectoryMetrics m;
  for (int i = 0; i <= 500; ++i) {
    PosePair p;
    p.t = i;
    p.gt.translation() = Vec3(i, 0, 0);
    p.est.translation() = Vec3(i, 2.0 * i / 500.0, 0);
    m.pairs.push_back(p);
    m.errors_m.push_back(2.0 * i / 500.0);
    m.distance_m.push_back(i);
  }
  m.ate.rmse_m = 1.16;
  return m;
}

cv::Vec3b turbo(double share) {
  cv::Mat level(1, 1, CV_8UC1, cv::Scalar(cv::saturate_cast<uchar>(255.0 * share))), bgr;
  cv::applyColorMap(level, bgr, cv::COLORMAP_TURBO);
  return bgr.at<cv::Vec3b>(0, 0);
}

int distance(const cv::Vec3b& a, const cv::Vec3b& b) {
  return std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]);
}

TEST(Plots, TopViewColoursTheEstimateByItsErrorOnTopOfTheGroundTruth) {
  const fs::path png = test::testTmp() / "trajectory_top.png";
  const TrajectoryMetrics m = straightDrive();
  plotTopView(png, m, 600);
  const cv::Mat img = cv::imread(png.string(), cv::IMREAD_COLOR);
  ASSERT_EQ(img.rows, 600);
  // The frame maps x 0..500 onto columns 40..560, the line at the image's middle row. A quarter of
  // the way along, the estimate (drawn on top, 2 px) has a quarter of the top error's colour.
  const TopViewFrame f({0.0, 0.0}, {500.0, 2.0}, 600, 40);
  for (double share : {0.25, 0.75}) {
    const Eigen::Vector2d p = f.pixel(500.0 * share, 2.0 * share);
    const cv::Vec3b got = img.at<cv::Vec3b>(static_cast<int>(p.y()), static_cast<int>(p.x()));
    EXPECT_LT(distance(got, turbo(share)), 40) << share << ": " << got;
    EXPECT_GT(distance(got, turbo(1.0 - share)), 100) << share;
  }
}

TEST(Plots, ErrorAlongDistanceHasGridlinesAtRoundValues) {
  const fs::path png = test::testTmp() / "error_along_distance.png";
  plotErrorAlongDistance(png, straightDrive(), 1000);
  const cv::Mat img = cv::imread(png.string(), cv::IMREAD_COLOR);
  ASSERT_EQ(img.cols, 1000);
  // x: 0..500 m on columns 60..980; ticks every 100 m (1, 2 or 5 times a power of ten giving at
  // most eight intervals). A vertical gridline is light grey over most of the plot's height.
  auto greyRows = [&](int col) {
    int n = 0;
    for (int r = 30; r < img.rows - 40; ++r)
      n += img.at<cv::Vec3b>(r, col) == cv::Vec3b(225, 225, 225);
    return n;
  };
  const int plot_rows = img.rows - 70;
  for (int d : {100, 200, 300, 400}) {
    const int col = 60 + static_cast<int>(d / 500.0 * 920);
    EXPECT_GT(greyRows(col), plot_rows / 2) << "no gridline at " << d << " m";
  }
  for (int d : {50, 150, 350})
    EXPECT_LT(greyRows(60 + static_cast<int>(d / 500.0 * 920)), 10) << "gridline at " << d << " m";
}

}  // namespace
}  // namespace slamroute::evaluate
