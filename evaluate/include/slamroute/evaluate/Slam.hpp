#pragma once
// The LeGO-LOAM-style pipeline (paper §3.3): per scan projection -> ground -> clusters ->
// features -> scan-to-scan odometry -> scan-to-map refinement; keyframes, ICP loop closure and a
// Ceres pose graph. The estimate starts at a given pose (the first ground-truth pose), so it is
// expressed in the world frame.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "slamroute/core/Odometry.hpp"
#include "slamroute/core/Scan.hpp"
#include "slamroute/core/Trajectory.hpp"
#include "slamroute/evaluate/Config.hpp"
#include "slamroute/evaluate/Features.hpp"

namespace slamroute::evaluate {

class MapSink;  // MapTiles.hpp

/// Why a frame's pose is (or is not) trustworthy.
enum class FrameStatus { Ok, Empty, Invalid, Missing, FewFeatures, Degenerate };
const char* toString(FrameStatus s);

struct StageTimes {  ///< accumulated CPU seconds (this thread) per stage
  double projection = 0, ground = 0, clustering = 0, features = 0, odometry = 0, mapping = 0,
         local_map = 0, loop_closure = 0, pose_graph = 0, total = 0;
};

struct LoopClosure {
  int from_keyframe = 0, to_keyframe = 0;  ///< old, new
  double t_old = 0, t_new = 0;
  double fitness_m2 = 0;
  double correction_m = 0;    ///< how far the ICP moved the new keyframe from its estimate [m]
  double correction_z_m = 0;  ///< ... of it upwards [m]
  Pose3 T_old_new = Pose3::Identity();  ///< the measured relative pose (for checks against truth)
  bool by_place = false;  ///< the candidate came from the place descriptor, not the estimate
};

struct SlamResult {
  Trajectory trajectory;            ///< one pose per scan, T_world_sensor
  std::vector<FrameStatus> status;  ///< per scan
  std::vector<double> min_eig;      ///< per scan: degeneracy measure of scan-to-map
  std::vector<LoopClosure> loops;   ///< accepted loop closures
  int loop_candidates = 0;          ///< ICP attempts
  int loops_rejected = 0;   ///< ICP matches refused as corrections the odometry cannot have drifted
  int loops_ambiguous = 0;  ///< ICP matches refused: ICP from nearby starts fits better elsewhere
  int keyframes = 0;
  double wheel_scale = 1.0;         ///< the wheels' scale measured by the LiDAR (1: not measured)
  double imu_pitch_bias_deg = 0.0;  ///< the IMU's pitch bias measured at loop closures [deg]
  StageTimes times;
  Cloud
      map;  ///< world frame, voxel-filtered (cfg.output.map_voxel_m); empty when a MapSink took it
  std::size_t map_points = 0;  ///< points of the map (also when a MapSink took it)
};

class LidarSlam {
 public:
  LidarSlam(const Config& cfg, const LidarSpec& spec, const Pose3& T_world_first);
  ~LidarSlam();
  LidarSlam(const LidarSlam&) = delete;
  LidarSlam& operator=(const LidarSlam&) = delete;
  /// Motion between the first two scans (body frame of the first), e.g. from wheel odometry or the
  /// ground truth; without it the first scan-to-map step starts from standstill.
  void setInitialMotion(const Pose3& T_first_second, double dt_s);
  /// Wheel odometry + gyro of the drive (sensor frame axes): predicts the motion between scans
  /// instead of the constant-velocity model, which carries the estimate through featureless
  /// stretches (open fields) and turns in them.
  void setOdometry(WheelOdometry odometry);
  /// Keeps the keyframes' clouds in an unnamed file in `dir` instead of memory (CloudStore.hpp);
  /// the results are the same bit for bit. Call before the first scan.
  void keepCloudsOnDisk(const std::filesystem::path& dir);
  /// finish() gives the map to `sink` tile by tile (MapTiles.hpp) instead of keeping it whole in
  /// SlamResult::map. `sink` must outlive finish().
  void setMapSink(MapSink& sink);
  /// Processes one scan; returns its status. Never throws on bad scan content.
  FrameStatus addScan(const Scan& scan);
  /// Records a scan that could not be read (constant-velocity prediction).
  FrameStatus addMissing(double t);
  /// Current pose estimate of the last frame.
  Pose3 currentPose() const;
  /// Turn rate [deg/s]: the gyro's at the last frame with odometry, else the current motion
  /// estimate's (0 before any motion is known).
  double turnRateDegPerS() const;
  /// True while the vehicle turns faster than cfg.input.dense_turn_rate_deg_s or within
  /// cfg.input.dense_after_failure_s of a failed or relocalised scan: the caller should then feed
  /// every scan instead of every cfg.input.scan_stride-th.
  bool wantsEveryScan() const;
  /// Ends the run and returns its results (trajectory, map, loops); call once: the keyframes'
  /// clouds are released as they are merged into the map.
  SlamResult finish();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// The scan after `i`: the next one while `every_scan`, else the next multiple of `stride`. The
/// strided scans stay on one grid (0, stride, 2 stride, ...) whatever dense stretches came before,
/// so two runs whose dense stretches differ (a failure in one, not the other) feed the same scans
/// again right after them, and their keyframes and loop-closure attempts stay in step.
inline std::size_t nextScanIndex(std::size_t i, std::size_t stride, bool every_scan) {
  if (every_scan || stride <= 1) return i + 1;
  return (i / stride + 1) * stride;
}

/// Runs the pipeline over a scan source: every cfg.input.scan_stride-th scan, and every scan while
/// the vehicle turns fast or after a failure (LidarSlam::wantsEveryScan). `T_first_second`: the
/// motion from the source's scan 0 to scan 1, if known. `odometry`: wheel speed + gyro (used when
/// cfg.odometry.use_wheel_odometry). `progress(done, total)` is called after each scan. A scan the
/// source cannot produce is recorded as Missing and the run continues. `cloud_dir`: where the
/// keyframe clouds go (LidarSlam::keepCloudsOnDisk; empty: memory). `map_sink`: where the map goes
/// (LidarSlam::setMapSink; null: SlamResult::map).
SlamResult runSlam(const ScanSource& source, const Config& cfg, const Pose3& T_world_first,
                   const std::function<void(std::size_t, std::size_t)>& progress = {},
                   const std::optional<Pose3>& T_first_second = std::nullopt,
                   const WheelOdometry* odometry = nullptr,
                   const std::filesystem::path& cloud_dir = {}, MapSink* map_sink = nullptr);

}  // namespace slamroute::evaluate
