// Odometry throughput and accuracy: scans/s on one core for 64x1800 scans end to end, with the
// time split by stage. Without arguments it drives a synthetic city street scene (analytic ray
// caster shared with the tests); with a drive folder that has scans/ it runs on those.
//   bench_odometry [--frames N] [--noise SIGMA_M] [--loop] [--no-loop-closure] [--drive DIR]
//                  [--config EVALUATE_SECTION.yaml]
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <numbers>
#include <string>

#include "../tests/evaluate/SyntheticScene.hpp"
#include "slamroute/core/ConfigIO.hpp"
#include "slamroute/core/DriveFolder.hpp"
#include "slamroute/core/Log.hpp"
#include "slamroute/evaluate/Evaluate.hpp"
#include "slamroute/simulate/SimulatedScanSource.hpp"

using namespace slamroute;
using namespace slamroute::evaluate;

namespace {

/// Ground-truth path: along the street y = 0, then (with --loop) around a block and back.
Trajectory syntheticPath(int frames, bool loop) {
  Trajectory gt;
  const double v = 1.0;  // m per frame (10 m/s at 10 Hz)
  // loop: rounded square (0,0) -> (80,0) -> (80,80) -> (0,80), along streets at multiples of 40
  const double L = 80.0;
  for (int i = 0; i < frames; ++i) {
    const double s = i * v;
    if (loop) {
      gt.push_back({0.1 * i, test::roundedLoopPose(s, L, 10.0)});
      continue;
    }
    gt.push_back({0.1 * i, test::poseXYZYaw(-100.0 + s, 0.0, 1.8, 0.0)});
  }
  return gt;
}

class SyntheticSource : public ScanSource {
 public:
  SyntheticSource(test::Scene scene, Trajectory gt, LidarSpec spec, double noise)
      : scene_(std::move(scene)), gt_(std::move(gt)), spec_(spec), noise_(noise) {}
  std::size_t size() const override { return gt_.size(); }
  double time(std::size_t i) const override { return gt_[i].t; }
  Scan scan(std::size_t i) const override {
    return test::scanScene(scene_, gt_[i].T_world_body, spec_, gt_[i].t, noise_, 1000 + i);
  }
  LidarSpec spec() const override { return spec_; }

 private:
  test::Scene scene_;
  Trajectory gt_;
  LidarSpec spec_;
  double noise_;
};

/// The first n scans of another source.
class Prefix : public ScanSource {
 public:
  Prefix(const ScanSource& s, std::size_t n) : s_(s), n_(std::min(n, s.size())) {}
  std::size_t size() const override { return n_; }
  double time(std::size_t i) const override { return s_.time(i); }
  Scan scan(std::size_t i) const override { return s_.scan(i); }
  LidarSpec spec() const override { return s_.spec(); }

 private:
  const ScanSource& s_;
  std::size_t n_;
};

void report(const SlamResult& r, const Trajectory& gt, const Config& cfg) {
  const TrajectoryMetrics m = compareTrajectories(r.trajectory, gt, metricsOptions(cfg));
  const StageTimes& t = r.times;
  const double n = static_cast<double>(r.trajectory.size());
  std::printf("scans %zu, keyframes %d, loop closures %zu (candidates %d)\n", r.trajectory.size(),
              r.keyframes, r.loops.size(), r.loop_candidates);
  std::printf(
      "route %.1f m, ATE rmse %.4f m mean %.4f max %.4f, RPE(%.0f m) %.3f %% %.5f deg/m, "
      "KITTI RPE %.3f %%\n",
      m.route_length_m, m.ate.rmse_m, m.ate.mean_m, m.ate.max_m, m.segment_m,
      m.rpe_segment.trans_pct, m.rpe_segment.rot_deg_per_m, m.rpe_kitti.trans_pct);
  std::printf(
      "ms/scan: projection %.2f ground %.2f clustering %.2f features %.2f odometry %.2f "
      "mapping %.2f local-map %.2f loop %.2f graph %.2f | total %.2f -> %.1f scans/s\n",
      1e3 * t.projection / n, 1e3 * t.ground / n, 1e3 * t.clustering / n, 1e3 * t.features / n,
      1e3 * t.odometry / n, 1e3 * t.mapping / n, 1e3 * t.local_map / n, 1e3 * t.loop_closure / n,
      1e3 * t.pose_graph / n, 1e3 * t.total / n, n / t.total);
  std::cout << "reliability: " << reliabilityJson(r)["by_reason"].dump() << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  int frames = -1;  // all scans of a drive; 300 synthetic
  double noise = 0.0;
  bool loop = false, no_lc = false;
  std::string drive, config_file;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--frames" && i + 1 < argc)
      frames = std::stoi(argv[++i]);
    else if (a == "--noise" && i + 1 < argc)
      noise = std::stod(argv[++i]);
    else if (a == "--loop")
      loop = true;
    else if (a == "--no-loop-closure")
      no_lc = true;
    else if (a == "--drive" && i + 1 < argc)
      drive = argv[++i];
    else if (a == "--config" && i + 1 < argc)
      config_file = argv[++i];
    else {
      std::cerr << "usage: bench_odometry [--frames N] [--noise M] [--loop] [--no-loop-closure] "
                   "[--drive DIR] [--config FILE]\n";
      return 2;
    }
  }
  Config cfg;
  cfg.loop.enabled = !no_lc;
  if (std::getenv("BENCH_DEBUG")) setLogLevel(LogLevel::Debug);
  if (!config_file.empty()) config::loadYaml(YAML::LoadFile(config_file), cfg, config_file);
  if (!drive.empty()) {
    const std::filesystem::path dir(drive);
    const LidarSpec spec = readSensorSpec(dir / drive_files::kSensor);
    std::unique_ptr<ScanSource> src;
    if (std::filesystem::is_directory(dir / drive_files::kScanDir))
      src = std::make_unique<KittiScanSource>(dir / drive_files::kScanDir, spec);
    else
      src = std::make_unique<simulate::SimulatedScanSource>(dir);
    const Trajectory gt = readTum(dir / drive_files::kGroundTruth);
    const Prefix part(*src, frames < 0 ? src->size() : static_cast<std::size_t>(frames));
    std::printf("drive %s: %zu of %zu scans\n", drive.c_str(), part.size(), src->size());
    const SlamResult r = runSlam(part, cfg, gt.front().T_world_body);
    report(r, gt, cfg);
    return 0;
  }
  const LidarSpec spec;  // 64 x 1800, +10/-30 deg, 100 m
  if (frames < 0) frames = 300;
  const Trajectory gt = syntheticPath(frames, loop);
  SyntheticSource src(test::cityScene(160.0), gt, spec, noise);
  std::printf("synthetic city, %d frames, 64x1800, noise %.3f m, %s\n", frames, noise,
              loop ? "loop around a block" : "straight street");
  const SlamResult r = runSlam(src, cfg, gt.front().T_world_body);
  report(r, gt, cfg);
  return 0;
}
