#pragma once
// Depth camera settings (paper §3.3: 800x600 depth images).
namespace slamroute::simulate {

struct DepthCameraConfig {
  void validate() const;   ///< values that cannot work: std::invalid_argument (ConfigValidate.cpp)
  int width = 800;         ///< image width [px] (paper: 800)
  int height = 600;        ///< image height [px] (paper: 600)
  double hfov_deg = 90.0;  ///< horizontal field of view [deg] (CARLA's default camera)
  double max_range_m = 65.0;   ///< farther returns are 0 (= no return); <= 65.535 for uint16 mm
  double range_sigma_m = 0.0;  ///< Gaussian depth noise, 1 sigma; 0 = noise-free [m]
};

template <class V>
void visitFields(V& v, DepthCameraConfig& c) {
  v.field("width", c.width, "image width [px]");
  v.field("height", c.height, "image height [px]");
  v.field("hfov_deg", c.hfov_deg, "horizontal field of view [deg]");
  v.field("max_range_m", c.max_range_m, "max depth, farther = 0 [m] (<= 65.535)");
  v.field("range_sigma_m", c.range_sigma_m, "Gaussian depth noise sigma [m]");
}

}  // namespace slamroute::simulate
