// LiDAR presets, KITTI .bin scan I/O and the file-backed scan source.
#include "slamroute/core/Scan.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "slamroute/core/AtomicFile.hpp"

namespace slamroute {

LidarSpec lidarPreset(const std::string& name) {
  LidarSpec s;
  if (name == "paper") {  // paper §4.1: 64 channels, 100 m, +10/-30 deg
    s.channels = 64, s.vfov_up_deg = 10.0, s.vfov_down_deg = -30.0, s.horizontal_samples = 1800;
    s.max_range_m = 100.0;
  } else if (name == "vlp16") {  // Velodyne VLP-16 (LeGO-LOAM's sensor): +-15 deg, 0.2 deg steps
    s.channels = 16, s.vfov_up_deg = 15.0, s.vfov_down_deg = -15.0, s.horizontal_samples = 1800;
    s.max_range_m = 100.0;
  } else if (name == "hdl32") {  // Velodyne HDL-32E: +10.67/-30.67 deg
    s.channels = 32, s.vfov_up_deg = 10.67, s.vfov_down_deg = -30.67, s.horizontal_samples = 1800;
    s.max_range_m = 100.0;
  } else {
    throw std::invalid_argument("unknown LiDAR preset '" + name + "' (paper|vlp16|hdl32)");
  }
  return s;
}

int ringFromElevation(const LidarSpec& spec, double x, double y, double z) {
  const double elev = std::atan2(z, std::hypot(x, y)) * 180.0 / M_PI;
  if (spec.channels <= 1) return 0;
  const double step = (spec.vfov_up_deg - spec.vfov_down_deg) / (spec.channels - 1);
  const int ring = static_cast<int>(std::lround((elev - spec.vfov_down_deg) / step));
  return (ring < 0 || ring >= spec.channels) ? -1 : ring;
}

void writeKittiScan(const std::filesystem::path& path, const Scan& scan) {
  std::string buf(scan.points.size() * 4 * sizeof(float), '\0');
  float* f = reinterpret_cast<float*>(buf.data());
  for (std::size_t i = 0; i < scan.points.size(); ++i) {
    const auto& p = scan.points[i];
    f[4 * i + 0] = p.x, f[4 * i + 1] = p.y, f[4 * i + 2] = p.z, f[4 * i + 3] = p.intensity;
  }
  if (scan.has_point_times) {
    std::string tbuf(scan.points.size() * sizeof(float), '\0');
    float* ft = reinterpret_cast<float*>(tbuf.data());
    for (std::size_t i = 0; i < scan.points.size(); ++i) ft[i] = scan.points[i].dt;
    writeFileAtomic(kittiPointTimesPath(path), tbuf);
  }
  writeFileAtomic(path, buf);
}

std::filesystem::path kittiPointTimesPath(const std::filesystem::path& bin_path) {
  std::filesystem::path p = bin_path;
  return p.replace_extension(".time");
}

Scan readKittiScan(const std::filesystem::path& path) {
  const std::string raw = readFile(path);
  if (raw.size() % (4 * sizeof(float)) != 0)
    throw std::runtime_error(path.string() +
                             ": size is not a multiple of 16 bytes (x,y,z,i float32)");
  Scan s;
  const std::size_t n = raw.size() / (4 * sizeof(float));
  s.points.resize(n);
  const float* f = reinterpret_cast<const float*>(raw.data());
  for (std::size_t i = 0; i < n; ++i)
    s.points[i] = {f[4 * i], f[4 * i + 1], f[4 * i + 2], f[4 * i + 3], -1, 0.0f};
  const std::filesystem::path tp = kittiPointTimesPath(path);
  if (std::filesystem::exists(tp)) {
    const std::string traw = readFile(tp);
    if (traw.size() != n * sizeof(float))
      throw std::runtime_error(tp.string() + ": " + std::to_string(traw.size() / sizeof(float)) +
                               " point times for " + std::to_string(n) + " points in " +
                               path.filename().string());
    const float* ft = reinterpret_cast<const float*>(traw.data());
    for (std::size_t i = 0; i < n; ++i) {
      if (!std::isfinite(ft[i]))
        throw std::runtime_error(tp.string() + ": point time " + std::to_string(i) +
                                 " is not finite");
      s.points[i].dt = ft[i];
    }
    s.has_point_times = true;
  }
  return s;
}

KittiScanSource::KittiScanSource(std::filesystem::path dir, LidarSpec spec)
    : KittiScanSource(dir, spec, dir / "times.txt") {}

KittiScanSource::KittiScanSource(std::filesystem::path dir, LidarSpec spec,
                                 const std::filesystem::path& times)
    : dir_(std::move(dir)), spec_(spec) {
  std::istringstream in(readFile(times));
  std::string line;
  while (std::getline(in, line)) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    try {
      times_.push_back(std::stod(line));
    } catch (const std::exception&) {
      throw std::invalid_argument(times.string() + ": bad time '" + line + "'");
    }
  }
  if (times_.empty()) throw std::invalid_argument(times.string() + ": no scans listed");
}

Scan KittiScanSource::scan(std::size_t i) const {
  char name[32];
  std::snprintf(name, sizeof name, "%06zu.bin", i);
  Scan s = readKittiScan(dir_ / name);
  s.t = times_.at(i);
  for (auto& p : s.points) p.ring = ringFromElevation(spec_, p.x, p.y, p.z);
  return s;
}

}  // namespace slamroute
