#pragma once
// Internal: what a World holds. Sensors (Lidar.cpp, DepthCamera.cpp) include this.
#include <string>
#include <unordered_map>

#include "WorldEmbree.hpp"
#include "slamroute/simulate/World.hpp"

namespace slamroute::simulate {

struct StreetInfo {
  StreetKind kind = StreetKind::Open;
  double richness = 0.0;
};

struct World::Impl {
  TriangleMesh mesh;
  WorldStats stats;
  double ground_z = 0.0;
  std::unordered_map<std::string, StreetInfo> streets;  ///< by SUMO edge id
  detail::EmbreeScene scene;
};

namespace detail {
/// Reflectivity in [0, 1] of a surface kind (used for intensities).
inline float reflectivity(SurfaceKind k) {
  switch (k) {
    case SurfaceKind::Ground:
      return 0.25f;
    case SurfaceKind::Road:
      return 0.12f;
    case SurfaceKind::Sidewalk:
      return 0.35f;
    case SurfaceKind::Deck:
      return 0.3f;
    case SurfaceKind::Pillar:
      return 0.4f;
    case SurfaceKind::Parapet:
      return 0.45f;
    case SurfaceKind::Building:
      return 0.5f;
    case SurfaceKind::Wall:
      return 0.4f;
    case SurfaceKind::Pole:
      return 0.8f;
    case SurfaceKind::Tree:
      return 0.3f;
    case SurfaceKind::Vehicle:
      return 0.7f;
    case SurfaceKind::Furniture:
      return 0.6f;
    case SurfaceKind::ParkedCar:
      return 0.65f;
    case SurfaceKind::Fence:
      return 0.35f;
  }
  return 0.3f;
}

/// Steps of World::build, in WorldRoads.cpp / WorldBuildings.cpp.
struct BuildContext;
}  // namespace detail

}  // namespace slamroute::simulate
