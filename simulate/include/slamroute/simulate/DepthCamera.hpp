#pragma once
// Simulated pinhole depth camera (paper §4.1: 800×600 depth images from CARLA).
//
// Camera frame (OpenCV convention): x right, y down, z forward (optical axis). A pose is
// T_world_camera. Pixel (u, v) (integer centres, u to the right, v down) looks along
// ((u − cx)/fx, (v − cy)/fy, 1) with fx = fy = (width/2)/tan(hfov/2), cx = (width−1)/2,
// cy = (height−1)/2. A pixel stores PLANAR depth (the z coordinate of the hit in the camera
// frame, as CARLA's depth camera does), in millimetres, rounded; 0 = no return within
// max_range_m. Back-projection: X = (u − cx)·Z/fx, Y = (v − cy)·Z/fy, Z = depth.
#include <cstdint>
#include <filesystem>
#include <vector>

#include "slamroute/core/Types.hpp"
#include "slamroute/simulate/DepthCameraConfig.hpp"
#include "slamroute/simulate/Traffic.hpp"
#include "slamroute/simulate/World.hpp"

namespace slamroute::simulate {

struct DepthImage {
  int width = 0, height = 0;
  std::vector<std::uint16_t> mm;  ///< row-major, width*height; 0 = no return
  std::uint16_t at(int u, int v) const {
    return mm[static_cast<std::size_t>(v) * static_cast<std::size_t>(width) +
              static_cast<std::size_t>(u)];
  }
};

class DepthCamera {
 public:
  /// Validates the config (sizes > 0, 0 < hfov < 180, 0 < max_range <= 65.535); throws
  /// std::invalid_argument naming the field.
  explicit DepthCamera(const DepthCameraConfig& cfg, std::uint64_t seed = 0);

  const DepthCameraConfig& config() const { return cfg_; }
  double fx() const { return f_; }
  double fy() const { return f_; }
  double cx() const { return (cfg_.width - 1) / 2.0; }
  double cy() const { return (cfg_.height - 1) / 2.0; }

  /// Renders the world (plus vehicle boxes) from T_world_camera. Noise (if range_sigma_m > 0)
  /// is drawn from (seed, frame_index, pixel), so a frame is reproducible.
  DepthImage render(const World& world, const Pose3& T_world_camera,
                    const std::vector<VehicleBox>& boxes = {}, std::size_t frame_index = 0) const;

  /// Camera mounted on a vehicle body (x forward, y left, z up), looking forward, `height_m`
  /// above the body origin, pitched down by `pitch_down_deg`: T_body_camera.
  static Pose3 bodyToCamera(double height_m, double pitch_down_deg = 0.0);

 private:
  DepthCameraConfig cfg_;
  std::uint64_t seed_;
  double f_;
};

/// 16-bit grayscale PNG (millimetres), written atomically. Throws std::runtime_error.
void writeDepthPng(const std::filesystem::path& path, const DepthImage& image);
/// Reads a 16-bit PNG written by writeDepthPng. Throws std::runtime_error naming the file.
DepthImage readDepthPng(const std::filesystem::path& path);

}  // namespace slamroute::simulate
