// writeDepthFrames: the survey's depth images (paper §3.1 input, 800x600 as in §4.1).
#include <cstdio>
#include <sstream>

#include "SurveyInternal.hpp"
#include "slamroute/core/AtomicFile.hpp"
#include "slamroute/core/Log.hpp"
#include "slamroute/simulate/DepthCamera.hpp"
#include "slamroute/simulate/World.hpp"

namespace slamroute::simulate {

void writeDepthFrames(const std::filesystem::path& dir, const SumoNet& net, const Config& cfg,
                      std::uint64_t seed, const std::vector<DepthShot>& shots) {
  std::filesystem::create_directories(dir);
  std::ostringstream index, edges;
  index << "frame,t,vehicle,x,y,z,qx,qy,qz,qw,width,height,file\n";
  edges << "frame,sumo_edge\n";
  if (!shots.empty()) {
    logInfo("survey: building the 3D world for " + std::to_string(shots.size()) + " depth frames");
    const World world = World::build(net, cfg.world, seed);
    const DepthCamera camera(cfg.depth, seed);
    const Pose3 T_body_camera = DepthCamera::bodyToCamera(0.0);  // height is in the shot pose
    Progress progress("depth frames", shots.size());
    for (std::size_t i = 0; i < shots.size(); ++i) {
      const DepthShot& s = shots[i];
      const Pose3 T_world_camera = s.T_world_body * T_body_camera;
      char name[32];
      std::snprintf(name, sizeof name, "%06zu.png", i);
      writeDepthPng(dir / name, camera.render(world, T_world_camera, {}, i));
      const Eigen::Quaterniond q(T_world_camera.linear());
      const Vec3 p = T_world_camera.translation();
      char line[256];
      std::snprintf(line, sizeof line, "%zu,%.2f,%s,%.3f,%.3f,%.3f,%.6f,%.6f,%.6f,%.6f,%d,%d,%s\n",
                    i, s.t, s.vehicle.c_str(), p.x(), p.y(), p.z(), q.x(), q.y(), q.z(), q.w(),
                    cfg.depth.width, cfg.depth.height, name);
      index << line;
      edges << i << "," << s.sumo_edge << "\n";
      progress.update(i + 1);
    }
    progress.finish();
  }
  writeFileAtomic(dir / "index.csv", index.str());
  writeFileAtomic(dir / "frame_edges.csv", edges.str());
}

}  // namespace slamroute::simulate
