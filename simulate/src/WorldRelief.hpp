#pragma once
// Internal: the relief of roads and ground in World::build — a seeded height field (metres-long
// swell plus centimetre roughness) that every road, pavement, junction and ground vertex samples
// at its own (x, y), so surfaces that meet share their heights.
#include <array>
#include <cstdint>

#include "slamroute/simulate/WorldConfig.hpp"

namespace slamroute::simulate::detail {

/// The rough ground lies this far below the road level (plus relief), so that a cambered road
/// stays above it; beyond the rough patches a flat base plane lies lower still.
constexpr double kGroundBelowRoad_m = 0.3;
constexpr double kBasePlaneBelow_m = 0.6;
/// Buildings, walls, poles and trunks start this far below the road level: their feet stay
/// inside the rough ground wherever it is.
constexpr double kFoundation_m = 0.8;
/// Camber lowers a road's edge by at most this (wide one-way roads) [m].
constexpr double kMaxCamberDrop_m = 0.12;
/// Camber fades in over this length from a lane's ends, so lanes meet junctions without a step.
constexpr double kCamberTaper_m = 6.0;

class Relief {
 public:
  Relief(const WorldConfig& c, std::uint64_t seed);
  /// Height offset of roads and pavements at (x, y) [m].
  double road(double x, double y) const { return swell(x, y) + road_sigma_ * rough(x, y); }
  /// Height offset of the ground beside roads [m].
  double verge(double x, double y) const { return swell(x, y) + verge_sigma_ * rough(x, y); }

 private:
  double swell(double x, double y) const;
  /// Value noise of unit sigma on a 0.5 m lattice (bilinear between seeded normal draws).
  double rough(double x, double y) const;
  double node(long ix, long iy) const;

  struct Wave {
    double kx = 0, ky = 0, phase = 0, amplitude = 0;
  };
  std::array<Wave, 4> waves_{};
  std::uint64_t key_ = 0;
  double road_sigma_ = 0, verge_sigma_ = 0;
};

}  // namespace slamroute::simulate::detail
