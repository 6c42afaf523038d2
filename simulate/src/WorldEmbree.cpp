#include "WorldEmbree.hpp"

#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

namespace slamroute::simulate::detail {

namespace {
void throwIfError(RTCDevice dev, const char* what) {
  const RTCError e = rtcGetDeviceError(dev);
  if (e != RTC_ERROR_NONE)
    throw std::runtime_error(std::string("Embree: ") + what + " failed (error " +
                             std::to_string(static_cast<int>(e)) + ")");
}
}  // namespace

EmbreeScene::EmbreeScene(const TriangleMesh& mesh) {
  // "threads=1" would make the build single-threaded; Embree's BVH builders are deterministic
  // either way, so the default thread pool is used (checked by the same-seed tests).
  device_ = rtcNewDevice("verbose=0");
  if (!device_) throw std::runtime_error("Embree: cannot create a device");
  scene_ = rtcNewScene(device_);
  rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
  if (!mesh.triangles.empty()) {
    RTCGeometry geom = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0,
                                                          RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                          mesh.vertices.size()));
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
      std::memcpy(v + 3 * i, mesh.vertices[i].data(), 3 * sizeof(float));
    auto* t = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0,
                                                             RTC_FORMAT_UINT3, 3 * sizeof(unsigned),
                                                             mesh.triangles.size()));
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i)
      for (int k = 0; k < 3; ++k) t[3 * i + k] = static_cast<unsigned>(mesh.triangles[i][k]);
    rtcSetGeometryBuildQuality(geom, RTC_BUILD_QUALITY_HIGH);
    rtcCommitGeometry(geom);
    rtcAttachGeometryByID(scene_, geom, 0);
    rtcReleaseGeometry(geom);
  }
  rtcCommitScene(scene_);
  throwIfError(device_, "scene build");
}

EmbreeScene::EmbreeScene(EmbreeScene&& o) noexcept : device_(o.device_), scene_(o.scene_) {
  o.device_ = nullptr;
  o.scene_ = nullptr;
}

EmbreeScene& EmbreeScene::operator=(EmbreeScene&& o) noexcept {
  if (this != &o) {
    release();
    device_ = o.device_;
    scene_ = o.scene_;
    o.device_ = nullptr;
    o.scene_ = nullptr;
  }
  return *this;
}

EmbreeScene::~EmbreeScene() { release(); }

void EmbreeScene::release() {
  if (scene_) rtcReleaseScene(scene_);
  if (device_) rtcReleaseDevice(device_);
  scene_ = nullptr;
  device_ = nullptr;
}

float EmbreeScene::intersect1(const Eigen::Vector3f& org, const Eigen::Vector3f& dir, float tnear,
                              float tfar, unsigned* prim, Eigen::Vector3f* ng) const {
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  RTCRayHit rh{};
  rh.ray.org_x = org.x();
  rh.ray.org_y = org.y();
  rh.ray.org_z = org.z();
  rh.ray.dir_x = dir.x();
  rh.ray.dir_y = dir.y();
  rh.ray.dir_z = dir.z();
  rh.ray.tnear = tnear;
  rh.ray.tfar = tfar;
  rh.ray.mask = 0xFFFFFFFFu;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene_, &ctx, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::numeric_limits<float>::infinity();
  if (prim) *prim = rh.hit.primID;
  if (ng) *ng = Eigen::Vector3f(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z);
  return rh.ray.tfar;
}

}  // namespace slamroute::simulate::detail
