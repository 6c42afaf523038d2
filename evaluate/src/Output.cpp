// map.pcd writer and the PNG plots (the module's only OpenCV translation unit).
#include "slamroute/evaluate/Output.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "slamroute/core/AtomicFile.hpp"

namespace slamroute::evaluate {
namespace {

void writePng(const std::filesystem::path& path, const cv::Mat& img) {
  std::vector<uchar> buf;
  if (!cv::imencode(".png", img, buf))
    throw std::runtime_error(path.string() + ": PNG encoding failed");
  writeFileAtomic(path, std::string(buf.begin(), buf.end()));
}

std::string fmt(double v, int prec = 2) {
  std::ostringstream os;
  os.setf(std::ios::fixed);
  os.precision(prec);
  os << v;
  return os.str();
}

/// A scale bar of a round length at the bottom left of a top view of `scale` px per m.
void drawScaleBar(cv::Mat& img, double scale, int margin) {
  const int S = img.rows;
  double bar = 1.0;
  while (bar * scale < S / 8.0) bar *= 10.0;
  if (bar * scale > S / 3.0) bar /= 2.0;
  const cv::Point b0(margin, S - 15), b1(margin + static_cast<int>(bar * scale), S - 15);
  cv::line(img, b0, b1, cv::Scalar(0, 0, 0), 2);
  cv::putText(img, fmt(bar, 0) + " m", b1 + cv::Point(5, 5), cv::FONT_HERSHEY_SIMPLEX, 0.45,
              cv::Scalar(0, 0, 0), 1);
}

/// A TURBO colour bar 150 px wide at (x, y), labelled "0 UNIT" and ">= TOP UNIT"; `caption` above.
void drawColourBar(cv::Mat& img, int x, int y, double top, const std::string& unit,
                   const std::string& caption) {
  const int bw = 150, bh = 10;
  cv::Mat ramp(1, bw, CV_8UC1);
  for (int i = 0; i < bw; ++i) ramp.at<uchar>(0, i) = static_cast<uchar>(255 * i / (bw - 1));
  cv::Mat ramp_bgr;
  cv::applyColorMap(ramp, ramp_bgr, cv::COLORMAP_TURBO);
  cv::resize(ramp_bgr, ramp_bgr, {bw, bh}, 0, 0, cv::INTER_NEAREST);
  ramp_bgr.copyTo(img(cv::Rect(x, y, bw, bh)));
  const cv::Scalar black(0, 0, 0);
  if (!caption.empty())
    cv::putText(img, caption, {x, y - 4}, cv::FONT_HERSHEY_SIMPLEX, 0.4, black, 1);
  cv::putText(img, "0 " + unit, {x, y + bh + 15}, cv::FONT_HERSHEY_SIMPLEX, 0.4, black, 1);
  cv::putText(img, ">= " + fmt(top, 2) + " " + unit, {x + bw - 55, y + bh + 15},
              cv::FONT_HERSHEY_SIMPLEX, 0.4, black, 1);
}

/// TURBO colour of `v` on a scale from 0 to `top`.
cv::Scalar turboColour(double v, double top) {
  cv::Mat level(1, 1, CV_8UC1, cv::Scalar(cv::saturate_cast<uchar>(255.0 * v / top))), bgr;
  cv::applyColorMap(level, bgr, cv::COLORMAP_TURBO);
  const cv::Vec3b c = bgr.at<cv::Vec3b>(0, 0);
  return cv::Scalar(c[0], c[1], c[2]);
}

/// Tick spacing of 1, 2 or 5 times a power of ten giving about `ticks` intervals over `range`.
double niceStep(double range, int ticks) {
  const double raw = range / std::max(1, ticks);
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  for (double f : {1.0, 2.0, 5.0})
    if (f * p >= raw) return f * p;
  return 10.0 * p;
}

/// Gridlines and labelled ticks at round values on both axes of a plot of [0, xmax] x [0, ymax];
/// `px` maps a value pair to its pixel.
template <class ToPixel>
void drawTicks(cv::Mat& img, double xmax, double ymax, const ToPixel& px) {
  const cv::Scalar grid(225, 225, 225), black(0, 0, 0);
  const double dx = niceStep(xmax, 8), dy = niceStep(ymax, 5);
  const int xprec = dx < 1 ? 1 : 0, yprec = dy < 0.01 ? 3 : dy < 0.1 ? 2 : dy < 1 ? 1 : 0;
  for (double x = 0; x <= xmax * (1 + 1e-9); x += dx) {
    cv::line(img, px(x, 0), px(x, ymax), grid, 1);
    const std::string label = fmt(x, xprec);
    cv::putText(img, label, px(x, 0) + cv::Point(-4 * static_cast<int>(label.size()), 18),
                cv::FONT_HERSHEY_SIMPLEX, 0.4, black, 1);
  }
  for (double y = 0; y <= ymax * (1 + 1e-9); y += dy) {
    cv::line(img, px(0, y), px(xmax, y), grid, 1);
    const std::string label = fmt(y, yprec);
    cv::putText(img, label, px(0, y) + cv::Point(-8 - 8 * static_cast<int>(label.size()), 4),
                cv::FONT_HERSHEY_SIMPLEX, 0.4, black, 1);
  }
}

std::string pcdHeader(std::size_t points) {
  std::ostringstream os;
  os << "# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\n"
     << "TYPE F F F\nCOUNT 1 1 1\nWIDTH " << points << "\nHEIGHT 1\n"
     << "VIEWPOINT 0 0 0 1 0 0 0\nPOINTS " << points << "\nDATA binary\n";
  return os.str();
}

static_assert(sizeof(Eigen::Vector3f) == 12, "PCD points are written as packed xyz floats");

void writePoints(std::ofstream& out, const Cloud& c) {
  out.write(reinterpret_cast<const char*>(c.data()),
            static_cast<std::streamsize>(c.size() * sizeof(Eigen::Vector3f)));
}

std::filesystem::path folderOf(const std::filesystem::path& path) {
  return path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
}

}  // namespace

void writePcd(const std::filesystem::path& path, const Cloud& cloud) {
  AtomicOutput out(path, true);
  out.stream() << pcdHeader(cloud.size());
  writePoints(out.stream(), cloud);
  out.commit();
}

PcdWriter::PcdWriter(std::filesystem::path path)
    : path_(std::move(path)),
      parts_(folderOf(path_), "the map's points for " + path_.filename().string()) {}

void PcdWriter::add(const Cloud& part) {
  if (part.empty()) return;
  parts_.add(part);
  points_ += part.size();
}

void PcdWriter::commit() {
  AtomicOutput out(path_, true);
  out.stream() << pcdHeader(points_);
  for (std::size_t i = 0; i < parts_.size(); ++i) {
    writePoints(out.stream(), parts_.get(static_cast<int>(i)));
    parts_.release(static_cast<int>(i));
  }
  out.commit();
}

TopViewFrame::TopViewFrame(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, int size_px,
                           int margin_px)
    : scale((size_px - 2 * margin_px) / std::max({hi.x() - lo.x(), hi.y() - lo.y(), 1.0})),
      size(size_px),
      centre(0.5 * (lo + hi)) {}

Eigen::Vector2d TopViewFrame::pixel(double x, double y) const {
  return {0.5 * size + (x - centre.x()) * scale, 0.5 * size - (y - centre.y()) * scale};
}

MapErrorImage::MapErrorImage(const Eigen::AlignedBox3f& bounds, int size_px)
    : size_(std::max(200, size_px)), margin_(40) {
  const auto pixels = static_cast<std::size_t>(size_) * static_cast<std::size_t>(size_);
  sum_.assign(pixels, 0.0f);
  count_.assign(pixels, 0);
  if (bounds.isEmpty()) return;
  frame_ = TopViewFrame(bounds.min().head<2>().cast<double>(),
                        bounds.max().head<2>().cast<double>(), size_, margin_);
}

std::size_t MapErrorImage::at(int row, int col) const {
  return static_cast<std::size_t>(row) * static_cast<std::size_t>(size_) +
         static_cast<std::size_t>(col);
}

bool MapErrorImage::pixel(double x, double y, int& col, int& row) const {
  const Eigen::Vector2d p = frame_.pixel(x, y);
  col = static_cast<int>(std::floor(p.x()));
  row = static_cast<int>(std::floor(p.y()));
  return frame_.scale > 0 && col >= 0 && row >= 0 && col < size_ && row < size_;
}

void MapErrorImage::add(const Cloud& part, const float* dist_m) {
  for (std::size_t i = 0; i < part.size(); ++i) {
    int c = 0, r = 0;
    if (!pixel(part[i].x(), part[i].y(), c, r)) continue;
    sum_[at(r, c)] += dist_m[i];
    ++count_[at(r, c)];
  }
}

double MapErrorImage::meanAt(double x, double y) const {
  int c = 0, r = 0;
  if (!pixel(x, y, c, r) || !count_[at(r, c)]) return std::numeric_limits<double>::quiet_NaN();
  return sum_[at(r, c)] / count_[at(r, c)];
}

double mapErrorImageTop(double aligned_p95_m, double max_m) {
  // Twice the p95 in 0.25 m steps (at most the clamp): a good map's centimetres and a broken
  // one's metres both show.
  return std::min(max_m, std::max(0.25, std::ceil(2.0 * aligned_p95_m / 0.25) * 0.25));
}

void MapErrorImage::write(const std::filesystem::path& path, const std::string& title,
                          double top_m) const {
  if (!(top_m > 0))
    throw std::invalid_argument("MapErrorImage: the colour scale's top must be positive");
  // Mean distance per pixel on the colour map (0 .. top_m), white where the map has no point.
  cv::Mat level(size_, size_, CV_8UC1, cv::Scalar(0)), empty(size_, size_, CV_8UC1, cv::Scalar(0));
  for (int r = 0; r < size_; ++r)
    for (int c = 0; c < size_; ++c) {
      const std::size_t k = at(r, c);
      if (count_[k])
        level.at<uchar>(r, c) = cv::saturate_cast<uchar>(255.0 * sum_[k] / count_[k] / top_m);
      else
        empty.at<uchar>(r, c) = 255;
    }
  cv::Mat img;
  cv::applyColorMap(level, img, cv::COLORMAP_TURBO);
  img.setTo(cv::Scalar(255, 255, 255), empty);
  cv::putText(img, title, {margin_, 20}, cv::FONT_HERSHEY_SIMPLEX, 0.5, cv::Scalar(0, 0, 0), 1);
  drawColourBar(img, size_ - margin_ - 150, 30, top_m, "m", "");
  if (frame_.scale > 0) drawScaleBar(img, frame_.scale, margin_);
  writePng(path, img);
}

void plotTopView(const std::filesystem::path& path, const TrajectoryMetrics& m, int size_px) {
  const int S = std::max(200, size_px), margin = 40;
  cv::Mat img(S, S, CV_8UC3, cv::Scalar(255, 255, 255));
  std::vector<Eigen::Vector2d> gt, est;
  Eigen::Vector2d lo(1e300, 1e300), hi(-1e300, -1e300);
  for (const auto& p : m.pairs) {
    gt.push_back(p.gt.translation().head<2>());
    est.push_back((m.T_gt_est * p.est.translation()).head<2>());
    for (const auto& q : {gt.back(), est.back()}) {
      lo = lo.cwiseMin(q);
      hi = hi.cwiseMax(q);
    }
  }
  if (gt.empty()) throw std::invalid_argument("plotTopView: empty trajectory");
  const TopViewFrame frame(lo, hi, S, margin);
  auto px = [&](const Eigen::Vector2d& q) {
    const Eigen::Vector2d p = frame.pixel(q.x(), q.y());
    return cv::Point(static_cast<int>(p.x()), static_cast<int>(p.y()));
  };
  // The ground truth underneath in grey, the estimate on top coloured by its error: at the scale
  // of a city a 2 m error is not visible as an offset, but it is as a colour.
  const double top = std::max(1e-3, *std::max_element(m.errors_m.begin(), m.errors_m.end()));
  for (std::size_t i = 1; i < gt.size(); ++i)
    cv::line(img, px(gt[i - 1]), px(gt[i]), cv::Scalar(170, 170, 170), 4, cv::LINE_AA);
  for (std::size_t i = 1; i < est.size(); ++i)
    cv::line(img, px(est[i - 1]), px(est[i]), turboColour(m.errors_m[i], top), 2, cv::LINE_AA);
  cv::circle(img, px(gt.front()), 5, cv::Scalar(0, 0, 0), 2);
  cv::putText(img, "estimate (aligned) coloured by its error over the ground truth (grey)",
              {margin, 20}, cv::FONT_HERSHEY_SIMPLEX, 0.45, cv::Scalar(0, 0, 0), 1);
  drawColourBar(img, S - margin - 150, 48, top, "m", "ATE RMSE " + fmt(m.ate.rmse_m, 3) + " m");
  drawScaleBar(img, frame.scale, margin);
  writePng(path, img);
}

void plotCurve(const std::filesystem::path& path, const std::vector<double>& x,
               const std::vector<double>& y, const std::string& title, int size_px, double y_max) {
  const int W = std::max(300, size_px), H = std::max(200, size_px / 2), ml = 60, mb = 40, mt = 30,
            mr = 20;
  cv::Mat img(H, W, CV_8UC3, cv::Scalar(255, 255, 255));
  if (x.empty() || x.size() != y.size())
    throw std::invalid_argument(path.string() +
                                ": a curve needs as many x as y values, at least one");
  const double dmax = std::max(1.0, x.back());
  const double emax =
      y_max > 0 ? y_max : std::max(1e-3, *std::max_element(y.begin(), y.end())) * 1.1;
  auto px = [&](double d, double e) {
    return cv::Point(static_cast<int>(ml + d / dmax * (W - ml - mr)),
                     static_cast<int>(H - mb - e / emax * (H - mb - mt)));
  };
  drawTicks(img, dmax, emax, px);
  cv::line(img, px(0, 0), px(dmax, 0), cv::Scalar(0, 0, 0), 1);
  cv::line(img, px(0, 0), px(0, emax), cv::Scalar(0, 0, 0), 1);
  for (std::size_t i = 1; i < y.size(); ++i)
    cv::line(img, px(x[i - 1], y[i - 1]), px(x[i], y[i]), cv::Scalar(200, 60, 0), 1, cv::LINE_AA);
  cv::putText(img, title, {ml, 20}, cv::FONT_HERSHEY_SIMPLEX, 0.5, cv::Scalar(0, 0, 0), 1);
  writePng(path, img);
}

void plotErrorAlongDistance(const std::filesystem::path& path, const TrajectoryMetrics& m,
                            int size_px) {
  if (m.errors_m.empty()) throw std::invalid_argument("plotErrorAlongDistance: empty trajectory");
  plotCurve(path, m.distance_m, m.errors_m, "ATE [m] vs distance [m]", size_px);
}

}  // namespace slamroute::evaluate
