// World export: PLY (binary little endian), OBJ, and a top-down height-coloured PNG.
#include <tbb/parallel_for.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

#include "WorldImpl.hpp"
#include "slamroute/core/AtomicFile.hpp"

namespace slamroute::simulate {

namespace {
template <class T>
void put(std::string& buf, T v) {  // little endian on x86-64
  char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  buf.append(b, sizeof(T));
}
}  // namespace

void World::writePly(const std::filesystem::path& path) const {
  const auto& m = impl_->mesh;
  std::string buf =
      "ply\nformat binary_little_endian 1.0\ncomment slamroute world mesh (net frame, metres)\n";
  buf += "element vertex " + std::to_string(m.vertices.size()) +
         "\nproperty float x\nproperty float y\nproperty float z\n";
  buf += "element face " + std::to_string(m.triangles.size()) +
         "\nproperty list uchar int vertex_indices\nend_header\n";
  buf.reserve(buf.size() + m.vertices.size() * 12 + m.triangles.size() * 13);
  for (const auto& v : m.vertices) {
    put(buf, v.x());
    put(buf, v.y());
    put(buf, v.z());
  }
  for (const auto& t : m.triangles) {
    put<std::uint8_t>(buf, 3);
    put<std::int32_t>(buf, t[0]);
    put<std::int32_t>(buf, t[1]);
    put<std::int32_t>(buf, t[2]);
  }
  writeFileAtomic(path, buf);
}

void World::writeObj(const std::filesystem::path& path) const {
  const auto& m = impl_->mesh;
  AtomicOutput out(path);
  auto& os = out.stream();
  os << "# slamroute world mesh (net frame, metres)\n";
  char line[96];
  for (const auto& v : m.vertices) {
    std::snprintf(line, sizeof line, "v %.3f %.3f %.3f\n", v.x(), v.y(), v.z());
    os << line;
  }
  for (int k = 0; k <= static_cast<int>(SurfaceKind::Last); ++k) {
    bool any = false;
    for (std::size_t i = 0; i < m.triangles.size(); ++i) {
      if (static_cast<int>(m.kinds[i]) != k) continue;
      if (!any) os << "g " << surfaceKindName(static_cast<SurfaceKind>(k)) << "\n";
      any = true;
      const auto& t = m.triangles[i];
      os << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << "\n";
    }
  }
  if (!os) throw std::runtime_error("cannot write " + path.string());
  out.commit();
}

void World::renderTopDownPng(const std::filesystem::path& path, double mpp) const {
  if (!(mpp > 0)) throw std::invalid_argument("renderTopDownPng: metres_per_pixel must be > 0");
  auto [lo, hi] = bounds();
  // crop the ground margin: use the extent of everything that is not ground
  Eigen::Vector3f a = Eigen::Vector3f::Constant(1e30f), b = -a;
  const auto& m = impl_->mesh;
  for (std::size_t i = 0; i < m.triangles.size(); ++i) {
    if (m.kinds[i] == SurfaceKind::Ground) continue;
    for (int k = 0; k < 3; ++k) {
      a = a.cwiseMin(m.vertices[static_cast<std::size_t>(m.triangles[i][k])]);
      b = b.cwiseMax(m.vertices[static_cast<std::size_t>(m.triangles[i][k])]);
    }
  }
  if (a.x() <= b.x()) {
    lo.head<2>() = a.head<2>().cast<double>() - Eigen::Vector2d(10, 10);
    hi.head<2>() = b.head<2>().cast<double>() + Eigen::Vector2d(10, 10);
  }
  mpp = std::max({mpp, (hi.x() - lo.x()) / 8000.0, (hi.y() - lo.y()) / 8000.0});  // <= 8000 px
  const int W = std::max(1, static_cast<int>((hi.x() - lo.x()) / mpp));
  const int H = std::max(1, static_cast<int>((hi.y() - lo.y()) / mpp));
  const double z0 = impl_->ground_z, ztop = hi.z() + 5.0;
  const double zspan = std::max(1.0, std::min(40.0, hi.z() - z0));
  cv::Mat img(H, W, CV_8UC3);
  const Eigen::Vector3f down(0, 0, -1);
  const Vec3 light = Vec3(-0.5, 0.5, 1.0).normalized();
  tbb::parallel_for(0, H, [&](int r) {
    for (int c = 0; c < W; ++c) {
      const Eigen::Vector3f o(static_cast<float>(lo.x() + (c + 0.5) * mpp),
                              static_cast<float>(hi.y() - (r + 0.5) * mpp),
                              static_cast<float>(ztop));
      unsigned prim = 0;
      Eigen::Vector3f ng;
      const float t = impl_->scene.intersect1(o, down, 0.f, 1e6f, &prim, &ng);
      cv::Vec3b px(40, 40, 40);
      if (std::isfinite(t)) {
        const double z = ztop - t;
        Vec3 n = ng.cast<double>().normalized();
        if (n.z() < 0) n = -n;
        const double shade = 0.55 + 0.45 * std::max(0.0, n.dot(light));
        const SurfaceKind k = m.kinds[prim];
        double R, G, B;
        if (k == SurfaceKind::Road || k == SurfaceKind::Deck) {
          const double g = 90 + 80 * std::clamp((z - z0) / 10.0, 0.0, 1.0);  // decks lighter
          R = G = B = g;
        } else if (k == SurfaceKind::Sidewalk) {
          R = G = B = 175;
        } else if (k == SurfaceKind::Ground) {
          R = 95, G = 125, B = 70;
        } else if (k == SurfaceKind::Tree) {
          R = 30, G = 140, B = 40;
        } else {  // height colour: blue (low) -> red (high)
          const double h = std::clamp((z - z0) / zspan, 0.0, 1.0);
          R = 255 * std::clamp(1.5 - std::abs(4 * h - 3), 0.0, 1.0);
          G = 255 * std::clamp(1.5 - std::abs(4 * h - 2), 0.0, 1.0);
          B = 255 * std::clamp(1.5 - std::abs(4 * h - 1), 0.0, 1.0);
        }
        px = cv::Vec3b(static_cast<uchar>(B * shade), static_cast<uchar>(G * shade),
                       static_cast<uchar>(R * shade));
      }
      img.at<cv::Vec3b>(r, c) = px;
    }
  });
  std::vector<uchar> png;
  if (!cv::imencode(".png", img, png)) throw std::runtime_error("cannot encode " + path.string());
  writeFileAtomic(path, std::string(png.begin(), png.end()));
}

}  // namespace slamroute::simulate
