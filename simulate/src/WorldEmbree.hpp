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

}  // namespace slamroute::simulate::detail
