// PCL against our own parts, the two places where PCL is the field's standard tool.
//  pcd ours|pcl POINTS: map.pcd of POINTS points in tiles of 100,000 (as the SLAM's map comes),
//    through our PcdWriter or through pcl::io::savePCDFileBinary (which needs the whole cloud as
//    one pcl::PointCloud); prints seconds and the process's peak memory. Run each in its own
//    process so that the peaks do not mix.
//  icp: our point-to-plane ICP (IcpTarget) and PCL's generalized ICP on pairs of scans of the
//    test street crossing (16 x 900 rays) at growing offsets: error against the truth, seconds.
// Usage: bench_pcl pcd ours|pcl POINTS | bench_pcl icp
#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>
#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <optional>
#include <string>

#include "../tests/evaluate/PclGicp.hpp"
#include "../tests/evaluate/SyntheticScene.hpp"
#include "slamroute/evaluate/Output.hpp"
#include "slamroute/evaluate/Registration.hpp"

using namespace slamroute;
using namespace slamroute::evaluate;
namespace fs = std::filesystem;

namespace {

constexpr std::size_t kTilePoints = 100000;

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

double peakMiB() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_maxrss) / 1024.0;
}

Cloud tile(std::size_t index) {
  Cloud c(kTilePoints);
  for (std::size_t i = 0; i < kTilePoints; ++i) {
    const float k = static_cast<float>(index * kTilePoints + i);
    c[i] = Eigen::Vector3f(0.01f * k, std::fmod(k, 997.0f), std::fmod(k, 31.0f));
  }
  return c;
}

int benchPcd(const std::string& writer, std::size_t points) {
  const fs::path dir = fs::temp_directory_path() / "bench_pcl";
  fs::create_directories(dir);
  const fs::path file = dir / (writer + ".pcd");
  const std::size_t tiles = points / kTilePoints;
  const double t0 = now();
  if (writer == "ours") {
    PcdWriter out(file);
    for (std::size_t i = 0; i < tiles; ++i) out.add(tile(i));
    out.commit();
  } else {
    pcl::PointCloud<pcl::PointXYZ> cloud;
    for (std::size_t i = 0; i < tiles; ++i)
      for (const auto& p : tile(i)) cloud.push_back({p.x(), p.y(), p.z()});
    pcl::io::savePCDFileBinary(file.string(), cloud);
  }
  std::printf("pcd %s: %zu points, %.2f s, peak %.0f MiB, %.0f MiB file\n", writer.c_str(),
              tiles * kTilePoints, now() - t0, peakMiB(),
              static_cast<double>(fs::file_size(file)) / (1024.0 * 1024.0));
  fs::remove_all(dir);
  return 0;
}

void printError(const char* who, const Pose3& truth, const Pose3& found, double seconds) {
  const Pose3 err = truth.inverse() * found;
  std::printf("  %-5s %.3f m %.3f deg %.3f s", who, err.translation().norm(),
              Eigen::AngleAxisd(err.rotation()).angle() * 180.0 / std::numbers::pi, seconds);
}

int benchIcp() {
  LidarSpec spec;
  spec.channels = 16;
  spec.horizontal_samples = 900;
  const evaluate::test::Scene scene = evaluate::test::cityScene(80.0);
  const Pose3 T_world_target = evaluate::test::poseXYZYaw(0.0, 0.0, 1.8, 0.0);
  const Cloud target =
      evaluate::test::cloudOf(evaluate::test::scanScene(scene, T_world_target, spec));
  for (double offset_m : {0.5, 1.0, 2.0, 3.0}) {
    const Pose3 T_world_source = evaluate::test::poseXYZYaw(
        offset_m, 0.5 * offset_m, 1.8, 2.0 * offset_m * std::numbers::pi / 180.0);
    const Cloud source =
        evaluate::test::cloudOf(evaluate::test::scanScene(scene, T_world_source, spec));
    const Pose3 truth = T_world_target.inverse() * T_world_source;
    double t0 = now();
    const IcpResult ours = IcpTarget(target).align(source, Pose3::Identity(), 30, 2.0);
    const double ours_s = now() - t0;
    t0 = now();
    const std::optional<Pose3> theirs = evaluate::test::pclGicp(target, source, 2.0, 30);
    const double pcl_s = now() - t0;
    std::printf("icp offset %.1f m, %zu/%zu points:", offset_m, source.size(), target.size());
    printError("ours", truth, ours.T_target_source, ours_s);
    if (theirs)
      printError("gicp", truth, *theirs, pcl_s);
    else
      std::printf("  gicp did not converge");
    std::printf("\n");
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string mode = argc > 1 ? argv[1] : "";
  if (mode == "pcd" && argc == 4) return benchPcd(argv[2], std::stoul(argv[3]));
  if (mode == "icp") return benchIcp();
  std::fprintf(stderr, "usage: bench_pcl pcd ours|pcl POINTS | bench_pcl icp\n");
  return 2;
}
