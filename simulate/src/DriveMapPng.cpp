// renderStackedScansPng: top-down view of scans stacked with ground-truth poses (each point from
// the pose at its firing time, so a moving sweep is drawn undistorted).
#include <algorithm>
#include <limits>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "slamroute/core/AtomicFile.hpp"
#include "slamroute/simulate/Drive.hpp"
#include "slamroute/simulate/Lidar.hpp"

namespace slamroute::simulate {

std::size_t renderStackedScansPng(const ScanSource& scans, const Trajectory& poses,
                                  const std::filesystem::path& png, const MapPngOptions& o) {
  if (scans.size() != poses.size())
    throw std::invalid_argument(png.string() + ": " + std::to_string(scans.size()) + " scans but " +
                                std::to_string(poses.size()) + " poses");
  if (!(o.metres_per_pixel > 0) || o.stride == 0 || !(o.z_max > o.z_min))
    throw std::invalid_argument(png.string() + ": bad map options");
  std::vector<Eigen::Vector3f> pts;
  for (std::size_t i = 0; i < scans.size(); i += o.stride) {
    // each point from where the sensor was when it fired (one pose per column's firing time)
    Eigen::Isometry3f T = poses[i].T_world_body.cast<float>();
    float t_of_T = 0.0f;
    for (const ScanPoint& p : scans.scan(i).points) {
      if (p.dt != t_of_T) {
        T = poseAtTime(poses, i, poses[i].t + p.dt).cast<float>();
        t_of_T = p.dt;
      }
      pts.push_back(T * Eigen::Vector3f(p.x, p.y, p.z));
    }
  }
  if (pts.empty()) throw std::runtime_error(png.string() + ": no points to draw");
  Eigen::Vector3f lo = Eigen::Vector3f::Constant(std::numeric_limits<float>::max()), hi = -lo;
  for (const auto& p : pts) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double res = o.metres_per_pixel;
  const int w = std::min(8000, static_cast<int>((hi.x() - lo.x()) / res) + 1);
  const int h = std::min(8000, static_cast<int>((hi.y() - lo.y()) / res) + 1);
  cv::Mat zmax(h, w, CV_32F, cv::Scalar(-std::numeric_limits<float>::max()));
  for (const auto& p : pts) {
    const int u = static_cast<int>((p.x() - lo.x()) / res);
    const int v = h - 1 - static_cast<int>((p.y() - lo.y()) / res);  // north up
    if (u < 0 || v < 0 || u >= w || v >= h) continue;
    float& z = zmax.at<float>(v, u);
    z = std::max(z, p.z());
  }
  cv::Mat grey(h, w, CV_8U, cv::Scalar(0)), mask(h, w, CV_8U, cv::Scalar(0));
  for (int v = 0; v < h; ++v)
    for (int u = 0; u < w; ++u) {
      const float z = zmax.at<float>(v, u);
      if (z < -1e30f) continue;
      const double s = std::clamp((z - o.z_min) / (o.z_max - o.z_min), 0.0, 1.0);
      grey.at<std::uint8_t>(v, u) = static_cast<std::uint8_t>(1 + 254 * s);
      mask.at<std::uint8_t>(v, u) = 255;
    }
  cv::Mat colour, out(h, w, CV_8UC3, cv::Scalar(0, 0, 0));
  cv::applyColorMap(grey, colour, cv::COLORMAP_JET);
  colour.copyTo(out, mask);
  std::vector<uchar> buf;
  if (!cv::imencode(".png", out, buf))
    throw std::runtime_error(png.string() + ": PNG encoding failed");
  writeFileAtomic(png, std::string(buf.begin(), buf.end()));
  return pts.size();
}

}  // namespace slamroute::simulate
