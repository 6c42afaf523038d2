#include "slamroute/pipeline/Plot.hpp"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "slamroute/core/AtomicFile.hpp"

namespace slamroute::pipeline {
namespace fs = std::filesystem;

namespace {

std::string fmt(double v, int prec) {
  std::ostringstream o;
  o << std::fixed << std::setprecision(prec) << v;
  return o.str();
}

}  // namespace

void scatterPng(const fs::path& path, const std::vector<double>& x, const std::vector<double>& y,
                const std::string& xlabel, const std::string& ylabel,
                const std::vector<std::string>& xticks) {
  const int W = 640, H = 480, m = 60;
  cv::Mat img(H, W, CV_8UC3, cv::Scalar(255, 255, 255));
  if (x.empty()) return;
  const auto [xmin, xmax] = std::minmax_element(x.begin(), x.end());
  const double x0 = xticks.empty() ? *xmin : -0.5;
  const double x1 = xticks.empty() ? std::max(*xmax, *xmin + 1e-9) : xticks.size() - 0.5;
  const double y0 = 0.0, y1 = std::max(*std::max_element(y.begin(), y.end()), 1e-9);
  cv::rectangle(img, {m, m / 2}, {W - m / 2, H - m}, cv::Scalar(0, 0, 0));
  auto px = [&](double v) { return m + static_cast<int>((v - x0) / (x1 - x0) * (W - 1.5 * m)); };
  for (std::size_t i = 0; i < x.size(); ++i) {
    const int py = H - m - static_cast<int>((y[i] - y0) / (y1 - y0) * (H - 1.5 * m));
    cv::circle(img, {px(x[i]), py}, 4, cv::Scalar(180, 90, 30), -1, cv::LINE_AA);
  }
  auto text = [&](const std::string& s, cv::Point p) {
    cv::putText(img, s, p, cv::FONT_HERSHEY_SIMPLEX, 0.45, cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
  };
  text(xlabel, {W / 2 - 80, H - 15});
  text(ylabel, {5, 20});
  if (xticks.empty()) {
    text(fmt(x0, 2), {m - 10, H - m + 18});
    text(fmt(x1, 2), {W - m, H - m + 18});
  } else {
    for (std::size_t i = 0; i < xticks.size(); ++i)
      text(xticks[i], {px(static_cast<double>(i)) - 20, H - m + 18});
  }
  text(fmt(y1, 1), {5, m / 2 + 5});
  text("0", {m - 15, H - m});
  std::vector<uchar> buf;
  cv::imencode(".png", img, buf);
  writeFileAtomic(path, std::string(buf.begin(), buf.end()));
}

}  // namespace slamroute::pipeline
