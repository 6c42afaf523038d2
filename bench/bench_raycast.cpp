// Ray throughput of the simulated LiDAR in the default city: scans of the default sensor (vlp16,
// 16 x 1800) swept while moving, from poses along the streets, single-thread and two-thread,
// and how rays could be issued instead (rtcIntersect1 one by one, rtcIntersect1M streams of a
// column, rtcIntersect16 packets of a column's rings; Lidar::scan packs one ring of 16
// neighbouring columns). Usage: bench_raycast [NET] [SCANS] [PRESET]  (vlp16, paper, hdl32)
#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <string>

#include "../simulate/src/WorldImpl.hpp"
#include "slamroute/core/SumoNet.hpp"
#include "slamroute/simulate/Lidar.hpp"
#include "slamroute/simulate/World.hpp"

using namespace slamroute;
using namespace slamroute::simulate;
namespace fs = std::filesystem;

namespace {

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
/// CPU seconds of the whole process (all threads): the machine is shared, so throughput per
/// core is rays / CPU second; wall-clock figures are printed too.
double cpuNow() {
  timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

std::vector<Pose3> posesAlongStreets(const SumoNet& net, std::size_t n) {
  std::vector<Pose3> out;
  for (std::size_t i = 0; out.size() < n && !net.edges.empty(); ++i) {
    const auto& e = net.edges[(i * 7) % net.edges.size()];
    if (!e.allowsPassenger() || e.lanes.front().shape.size() < 2) continue;
    const auto& s = e.lanes.front().shape;
    const Vec3 a = s[0], b = s[1];
    Pose3 T = Pose3::Identity();
    T.linear() = Eigen::AngleAxisd(std::atan2(b.y() - a.y(), b.x() - a.x()), Vec3::UnitZ())
                     .toRotationMatrix();
    T.translation() = 0.5 * (a + b) + Vec3(0, 0, 1.8);
    out.push_back(T);
  }
  return out;
}

/// Where the sensor is at the end of a sweep that starts at T: a car at 50 km/h (1.4 m per
/// 0.1 s sweep) turning 0.5 degrees, so each column is cast from its own pose as in a drive.
Pose3 sweepEnd(const Pose3& T) {
  Pose3 step = Pose3::Identity();
  step.linear() = Eigen::AngleAxisd(0.5 * M_PI / 180.0, Vec3::UnitZ()).toRotationMatrix();
  step.translation() = Vec3(1.4, 0, 0);
  return T * step;
}

/// The same rays as Lidar::scan, issued with rtcIntersect1 (one) or rtcIntersect1M (a column).
double castPlain(const World& w, const Lidar& lidar, const std::vector<Pose3>& poses, int mode) {
  const bool stream = mode == 1;
  const auto& spec = lidar.spec();
  const RTCScene scene = w.impl().scene.scene();
  std::vector<RTCRayHit> rays(static_cast<std::size_t>(spec.channels));
  double hits = 0;
  for (const auto& T : poses) {
    const Eigen::Vector3f o = T.translation().cast<float>();
    const Eigen::Matrix3f R = T.linear().cast<float>();
    for (int c = 0; c < spec.horizontal_samples; ++c) {
      const double az = lidar.azimuthRad(c);
      for (int r = 0; r < spec.channels; ++r) {
        const double el = lidar.elevationRad(r);
        const Eigen::Vector3f d = R * Eigen::Vector3f(std::cos(el) * std::cos(az),
                                                      std::cos(el) * std::sin(az), std::sin(el));
        RTCRayHit& h = rays[static_cast<std::size_t>(r)];
        h = RTCRayHit{};
        h.ray.org_x = o.x(), h.ray.org_y = o.y(), h.ray.org_z = o.z();
        h.ray.dir_x = d.x(), h.ray.dir_y = d.y(), h.ray.dir_z = d.z();
        h.ray.tnear = 0, h.ray.tfar = static_cast<float>(spec.max_range_m), h.ray.mask = ~0u;
        h.hit.geomID = RTC_INVALID_GEOMETRY_ID;
      }
      RTCIntersectContext ctx;
      rtcInitIntersectContext(&ctx);
      if (mode == 2) {
        for (std::size_t r0 = 0; r0 < rays.size(); r0 += 16) {
          alignas(64) RTCRayHit16 p;
          alignas(64) int valid[16];
          for (std::size_t k = 0; k < 16; ++k) {
            const bool ok = r0 + k < rays.size();
            valid[k] = ok ? -1 : 0;
            const RTCRayHit& h = rays[ok ? r0 + k : r0];
            p.ray.org_x[k] = h.ray.org_x, p.ray.org_y[k] = h.ray.org_y,
            p.ray.org_z[k] = h.ray.org_z;
            p.ray.dir_x[k] = h.ray.dir_x, p.ray.dir_y[k] = h.ray.dir_y,
            p.ray.dir_z[k] = h.ray.dir_z;
            p.ray.tnear[k] = 0, p.ray.tfar[k] = h.ray.tfar, p.ray.mask[k] = ~0u, p.ray.time[k] = 0;
            p.ray.flags[k] = 0, p.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
          }
          ctx.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
          rtcIntersect16(valid, scene, &ctx, &p);
          for (std::size_t k = 0; k < 16 && r0 + k < rays.size(); ++k)
            rays[r0 + k].hit.geomID = p.hit.geomID[k];
        }
      } else if (stream) {
        ctx.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
        rtcIntersect1M(scene, &ctx, rays.data(), static_cast<unsigned>(rays.size()),
                       sizeof(RTCRayHit));
      } else {
        for (auto& h : rays) rtcIntersect1(scene, &ctx, &h);
      }
      for (const auto& h : rays) hits += h.hit.geomID != RTC_INVALID_GEOMETRY_ID;
    }
  }
  return hits;
}

}  // namespace

int main(int argc, char** argv) {
  fs::path net_path =
      argc > 1 ? fs::path(argv[1])
               : fs::path(SLAMROUTE_SOURCE_DIR) / "networks/default_city/default_city.net.xml";
  if (argc <= 1 && !fs::exists(net_path))
    net_path = fs::path(SLAMROUTE_SHARED_DIR) / "networks/bologna_acosta/acosta_buslanes.net.xml";
  const std::size_t n_scans = argc > 2 ? std::stoul(argv[2]) : 40;
  const SumoNet net = SumoNet::read(net_path);
  double t0 = now();
  const World world = World::build(net, WorldConfig{}, 42);
  const double t_build = now() - t0;
  LidarConfig cfg;  // the default sensor (vlp16: 16 x 1800), 2 cm noise, 1 % dropout
  if (argc > 3) cfg.preset = argv[3];
  const Lidar lidar(cfg, 42);
  const auto poses = posesAlongStreets(net, n_scans);
  const double rays =
      static_cast<double>(poses.size()) * lidar.spec().channels * lidar.spec().horizontal_samples;
  std::printf("net %s\nworld: %zu triangles, built in %.2f s\n%zu scans of %dx%d = %.0f rays\n",
              net_path.string().c_str(), world.mesh().triangles.size(), t_build, poses.size(),
              lidar.spec().channels, lidar.spec().horizontal_samples, rays);
  double points = 0;
  LidarConfig quiet = cfg;
  quiet.range_sigma_m = 0;
  quiet.dropout_prob = 0;
  const Lidar noiseless(quiet, 42);
  for (const Lidar* l : {&lidar, &noiseless})
    for (int threads : {1, 2}) {
      tbb::task_arena arena(threads);
      arena.execute([&] { l->scan(world, poses[0], {}, 0); });  // warm-up
      t0 = now();
      const double c0 = cpuNow();
      arena.execute([&] {
        points = 0;
        for (std::size_t i = 0; i < poses.size(); ++i)
          points += l->scan(world, poses[i], sweepEnd(poses[i]), {}, i).points.size();
      });
      const double dt = now() - t0, dc = cpuNow() - c0;
      std::printf(
          "Lidar::scan%s, %d thread(s): %.2f M rays/s wall, %.2f M rays per CPU-second, "
          "%.1f ms/scan wall, %.0f points/scan\n",
          l == &lidar ? "" : " (noise off)", threads, rays / dt / 1e6, rays / dc / 1e6,
          1e3 * dt / poses.size(), points / poses.size());
    }
  for (int stream : {0, 1, 2}) {
    t0 = now();
    const double c0 = cpuNow();
    const double hits = castPlain(world, lidar, poses, stream);
    const double dt = now() - t0, dc = cpuNow() - c0;
    std::printf("%s, 1 thread: %.2f M rays/s wall, %.2f M rays per CPU-second (%.0f hits/scan)\n",
                stream == 1   ? "rtcIntersect1M (coherent stream of a column)"
                : stream == 2 ? "rtcIntersect16 (packets of 16 rings of a column)"
                              : "rtcIntersect1 (one ray at a time)",
                rays / dt / 1e6, rays / dc / 1e6, hits / poses.size());
  }
  return 0;
}
