#include "slamroute/simulate/DepthCamera.hpp"

#include <tbb/parallel_for.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include <cmath>
#include <stdexcept>

#include "LidarNoise.hpp"
#include "WorldBoxes.hpp"
#include "WorldImpl.hpp"
#include "slamroute/core/AtomicFile.hpp"

namespace slamroute::simulate {

DepthCamera::DepthCamera(const DepthCameraConfig& cfg, std::uint64_t seed)
    : cfg_(cfg), seed_(seed) {
  try {
    cfg.validate();
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("simulate.depth: ") + e.what());
  }
  f_ = (cfg.width / 2.0) / std::tan(cfg.hfov_deg * M_PI / 360.0);
}

Pose3 DepthCamera::bodyToCamera(double height_m, double pitch_down_deg) {
  // camera z = body x (forward), camera x = -body y (right), camera y = -body z (down)
  Mat3 R_body_cam;
  R_body_cam << 0, 0, 1, -1, 0, 0, 0, -1, 0;
  const Mat3 pitch =
      Eigen::AngleAxisd(pitch_down_deg * M_PI / 180.0, Vec3::UnitY()).toRotationMatrix();
  Pose3 T = Pose3::Identity();
  T.linear() = pitch * R_body_cam;
  T.translation() = Vec3(0, 0, height_m);
  return T;
}

DepthImage DepthCamera::render(const World& world, const Pose3& T_wc,
                               const std::vector<VehicleBox>& boxes, std::size_t frame) const {
  const int W = cfg_.width, H = cfg_.height;
  DepthImage img;
  img.width = W;
  img.height = H;
  img.mm.assign(static_cast<std::size_t>(W) * H, 0);
  std::vector<detail::PreparedBox> pb;
  for (const auto& b : boxes) pb.push_back(detail::prepareBox(b));
  const Eigen::Matrix3f R = T_wc.linear().cast<float>();
  const Eigen::Vector3f o = T_wc.translation().cast<float>();
  const Vec3 od = T_wc.translation();
  const RTCScene scene = world.impl().scene.scene();
  const float maxz = static_cast<float>(cfg_.max_range_m);
  const double cxv = cx(), cyv = cy();
  const int tiles_x = (W + 3) / 4, tiles_y = (H + 3) / 4;
  // 4x4 pixel tiles as 16-ray packets; the ray direction has camera-frame z = 1, so Embree's
  // t is the planar depth directly.
  tbb::parallel_for(0, tiles_y, [&](int ty) {
    RTCIntersectContext ctx;
    alignas(64) RTCRayHit16 rh;
    alignas(64) int mask[16];
    for (int tx = 0; tx < tiles_x; ++tx) {
      rtcInitIntersectContext(&ctx);
      ctx.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
      for (int k = 0; k < 16; ++k) {
        const int u = tx * 4 + (k & 3), v = ty * 4 + (k >> 2);
        mask[k] = (u < W && v < H) ? -1 : 0;
        const Eigen::Vector3f d = R * Eigen::Vector3f(static_cast<float>((u - cxv) / f_),
                                                      static_cast<float>((v - cyv) / f_), 1.0f);
        detail::setRay16(rh, k, o, d, maxz);
      }
      rtcIntersect16(mask, scene, &ctx, &rh);
      for (int k = 0; k < 16; ++k) {
        if (!mask[k]) continue;
        const int u = tx * 4 + (k & 3), v = ty * 4 + (k >> 2);
        double z = rh.hit.geomID[k] != RTC_INVALID_GEOMETRY_ID ? rh.ray.tfar[k] : INFINITY;
        const Vec3 d(rh.ray.dir_x[k], rh.ray.dir_y[k], rh.ray.dir_z[k]);
        for (const auto& b : pb) {
          double tb;
          Vec3 nb;
          if (detail::intersectBox(b, od, d, std::min<double>(z, maxz), &tb, &nb)) z = tb;
        }
        if (!std::isfinite(z)) continue;
        const std::size_t idx = static_cast<std::size_t>(v) * W + u;
        if (cfg_.range_sigma_m > 0)
          z += cfg_.range_sigma_m * detail::RayRandom(seed_, frame, idx).normal();
        const double mm = std::round(z * 1000.0);
        if (mm >= 1.0 && z <= cfg_.max_range_m)
          img.mm[idx] = static_cast<std::uint16_t>(std::min(mm, 65535.0));
      }
    }
  });
  return img;
}

void writeDepthPng(const std::filesystem::path& path, const DepthImage& image) {
  if (image.width < 1 || image.height < 1 ||
      image.mm.size() != static_cast<std::size_t>(image.width) * image.height)
    throw std::invalid_argument("writeDepthPng " + path.string() + ": image size mismatch");
  const cv::Mat m(image.height, image.width, CV_16UC1, const_cast<std::uint16_t*>(image.mm.data()));
  std::vector<uchar> png;
  if (!cv::imencode(".png", m, png)) throw std::runtime_error("cannot encode " + path.string());
  writeFileAtomic(path, std::string(png.begin(), png.end()));
}

DepthImage readDepthPng(const std::filesystem::path& path) {
  const cv::Mat m = cv::imread(path.string(), cv::IMREAD_ANYDEPTH);
  if (m.empty()) throw std::runtime_error("cannot read depth image " + path.string());
  if (m.type() != CV_16UC1)
    throw std::runtime_error(path.string() + ": not a 16-bit single-channel PNG");
  DepthImage img;
  img.width = m.cols;
  img.height = m.rows;
  img.mm.resize(static_cast<std::size_t>(m.cols) * m.rows);
  for (int r = 0; r < m.rows; ++r)
    for (int c = 0; c < m.cols; ++c)
      img.mm[static_cast<std::size_t>(r) * m.cols + c] = m.at<std::uint16_t>(r, c);
  return img;
}

}  // namespace slamroute::simulate
