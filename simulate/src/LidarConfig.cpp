#include "slamroute/simulate/LidarConfig.hpp"

#include <stdexcept>

namespace slamroute::simulate {

LidarSpec resolveLidarSpec(const LidarConfig& cfg) {
  const LidarSpec def;
  LidarSpec s = (cfg.preset.empty() || cfg.preset == "custom") ? def : lidarPreset(cfg.preset);
  const LidarSpec& o = cfg.spec;
  // fields set away from the defaults override the preset
  if (o.channels != def.channels) s.channels = o.channels;
  if (o.vfov_up_deg != def.vfov_up_deg) s.vfov_up_deg = o.vfov_up_deg;
  if (o.vfov_down_deg != def.vfov_down_deg) s.vfov_down_deg = o.vfov_down_deg;
  if (o.horizontal_samples != def.horizontal_samples) s.horizontal_samples = o.horizontal_samples;
  if (o.max_range_m != def.max_range_m) s.max_range_m = o.max_range_m;
  if (o.min_range_m != def.min_range_m) s.min_range_m = o.min_range_m;
  if (o.mount_height_m != def.mount_height_m) s.mount_height_m = o.mount_height_m;
  auto bad = [](const std::string& m) { throw std::invalid_argument("simulate.lidar: " + m); };
  if (s.channels < 1 || s.channels > 1024) bad("channels must be in [1, 1024]");
  if (s.horizontal_samples < 1 || s.horizontal_samples > 100000)
    bad("horizontal_samples must be in [1, 100000]");
  if (s.channels > 1 && !(s.vfov_up_deg > s.vfov_down_deg))
    bad("vfov_up_deg must exceed vfov_down_deg");
  if (s.vfov_up_deg > 90 || s.vfov_down_deg < -90) bad("vertical field outside [-90, 90] deg");
  if (!(s.min_range_m >= 0) || !(s.max_range_m > s.min_range_m))
    bad("need 0 <= min_range_m < max_range_m");
  return s;
}

}  // namespace slamroute::simulate
