#include "WorldRelief.hpp"

#include <cmath>
#include <numbers>

#include "LidarNoise.hpp"

namespace slamroute::simulate::detail {

namespace {
constexpr double kLattice_m = 0.5;
/// Bilinear interpolation of unit-sigma nodes has sigma 2/3 at random points; this restores 1.
constexpr double kBilinearGain = 1.5;

double unit(std::uint64_t& state) {
  state = splitmix(state);
  return (static_cast<double>(state >> 11) + 0.5) * (1.0 / 9007199254740992.0);
}
}  // namespace

Relief::Relief(const WorldConfig& c, std::uint64_t seed)
    : key_(splitmix(seed ^ 0x72656c696566ULL)),  // "relief": its own stream
      road_sigma_(c.road_roughness_m),
      verge_sigma_(c.verge_roughness_m) {
  std::uint64_t s = key_;
  // four plane waves in random directions: their sum has sigma amplitude * sqrt(4 / 2)
  const double amplitude = c.undulation_m / std::sqrt(2.0);
  for (auto& w : waves_) {
    const double dir = 2 * std::numbers::pi * unit(s);
    const double wavelength = c.undulation_wavelength_m * (0.5 + unit(s));
    const double k = 2 * std::numbers::pi / wavelength;
    w.kx = k * std::cos(dir);
    w.ky = k * std::sin(dir);
    w.phase = 2 * std::numbers::pi * unit(s);
    w.amplitude = amplitude;
  }
}

double Relief::swell(double x, double y) const {
  double z = 0;
  for (const auto& w : waves_) z += w.amplitude * std::sin(w.kx * x + w.ky * y + w.phase);
  return z;
}

double Relief::node(long ix, long iy) const {
  const std::uint64_t h =
      splitmix(key_ ^ splitmix(static_cast<std::uint64_t>(ix) * 0x9e3779b97f4a7c15ULL +
                               static_cast<std::uint64_t>(iy)));
  return RayRandom::inverseNormalCdf((static_cast<double>(h >> 11) + 0.5) *
                                     (1.0 / 9007199254740992.0));
}

double Relief::rough(double x, double y) const {
  const double gx = x / kLattice_m, gy = y / kLattice_m;
  const double fx0 = std::floor(gx), fy0 = std::floor(gy);
  const long ix = static_cast<long>(fx0), iy = static_cast<long>(fy0);
  const double u = gx - fx0, v = gy - fy0;
  const double a = node(ix, iy) * (1 - u) + node(ix + 1, iy) * u;
  const double b = node(ix, iy + 1) * (1 - u) + node(ix + 1, iy + 1) * u;
  return kBilinearGain * (a * (1 - v) + b * v);
}

}  // namespace slamroute::simulate::detail
