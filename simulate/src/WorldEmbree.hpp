#pragma once
// Internal: RAII Embree device + scene holding the static triangle mesh (one geometry).
#include <embree3/rtcore.h>

#include "slamroute/simulate/World.hpp"

namespace slamroute::simulate::detail {

class EmbreeScene {
 public:
  EmbreeScene() = default;
  explicit EmbreeScene(const TriangleMesh& mesh);
  EmbreeScene(EmbreeScene&& o) noexcept;
  EmbreeScene& operator=(EmbreeScene&& o) noexcept;
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;
  ~EmbreeScene();

  RTCScene scene() const { return scene_; }
  /// One ray; returns t (or +inf) and the primitive id and unnormalised geometric normal.
  float intersect1(const Eigen::Vector3f& org, const Eigen::Vector3f& dir, float tnear, float tfar,
                   unsigned* prim, Eigen::Vector3f* ng) const;

 private:
  void release();
  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
};

/// Lane k of a packet of 16 rays: origin, direction, [0, tfar], no hit yet.
inline void setRay16(RTCRayHit16& rh, int k, const Eigen::Vector3f& org, const Eigen::Vector3f& dir,
                     float tfar) {
  rh.ray.org_x[k] = org.x();
  rh.ray.org_y[k] = org.y();
  rh.ray.org_z[k] = org.z();
  rh.ray.dir_x[k] = dir.x();
  rh.ray.dir_y[k] = dir.y();
  rh.ray.dir_z[k] = dir.z();
  rh.ray.tnear[k] = 0.0f;
  rh.ray.tfar[k] = tfar;
  rh.ray.mask[k] = 0xFFFFFFFFu;
  rh.ray.time[k] = 0.0f;
  rh.ray.flags[k] = 0;
  rh.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0][k] = RTC_INVALID_GEOMETRY_ID;
}

}  // namespace slamroute::simulate::detail
