#pragma once
// Simulated spinning multi-beam LiDAR (paper §3.3/§4.1: 64 channels, +10°/−30°, 100 m).
//
// Geometry: ring r (0 = lowest beam, LeGO-LOAM's row order) has elevation
//   vfov_down + (vfov_up − vfov_down)·r/(channels − 1);
// column c has azimuth 2π·c/horizontal_samples, counter-clockwise from the sensor's +x.
// Sensor frame: x forward, y left, z up (KITTI velodyne). The sensor spins: column c fires at
// c / horizontal_samples of the sweep period after the scan's time, from where the moving sensor
// is then (the pose interpolated between the sweep's start and end), and its points are in the
// sensor frame of that moment with their firing time in ScanPoint::dt — a raw scan, distorted
// by the motion as a real one (LidarConfig::motion_distortion; off: one pose per sweep).
// Returns closer than min_range or beyond max_range are dropped. Noise: Gaussian range noise
// (sigma range_sigma_m) along the beam and random dropout, drawn from a counter-based hash of
// (seed, scan index, ray index), so a scan is bitwise reproducible whatever the thread count.
// Intensity = surface reflectivity × |cos(incidence angle)| in [0, 1].
// Points are ordered column by column, rings ascending within a column.
#include <cstdint>
#include <vector>

#include "slamroute/core/Scan.hpp"
#include "slamroute/core/Trajectory.hpp"
#include "slamroute/core/Types.hpp"
#include "slamroute/simulate/LidarConfig.hpp"
#include "slamroute/simulate/Traffic.hpp"
#include "slamroute/simulate/World.hpp"

namespace slamroute::simulate {

class Lidar {
 public:
  /// Resolves the spec (resolveLidarSpec) and validates the noise settings; throws
  /// std::invalid_argument naming the bad field.
  Lidar(const LidarConfig& cfg, std::uint64_t seed);

  const LidarSpec& spec() const { return spec_; }
  const LidarConfig& config() const { return cfg_; }
  double elevationRad(int ring) const;
  double azimuthRad(int column) const;

  /// One sweep among the static world and the given vehicle boxes (standing still during the
  /// sweep), the sensor moving from T_start (at t) to T_end (one sweep period later). Uses TBB
  /// inside the scan; the result does not depend on the thread count.
  Scan scan(const World& world, const Pose3& T_start, const Pose3& T_end,
            const std::vector<VehicleBox>& boxes, std::size_t scan_index, double t = 0.0) const;
  /// A sweep of a standing sensor.
  Scan scan(const World& world, const Pose3& T_world_sensor, const std::vector<VehicleBox>& boxes,
            std::size_t scan_index, double t = 0.0) const {
    return scan(world, T_world_sensor, T_world_sensor, boxes, scan_index, t);
  }

  /// Many scans in parallel (TBB over scans); scan k sweeps from starts[k] to ends[k] with index
  /// first_index + k and boxes[k] (boxes may be empty = no traffic anywhere, else one entry per
  /// scan; times likewise).
  std::vector<Scan> scanMany(const World& world, const std::vector<Pose3>& starts,
                             const std::vector<Pose3>& ends,
                             const std::vector<std::vector<VehicleBox>>& boxes,
                             std::size_t first_index, const std::vector<double>& times = {}) const;

 private:
  LidarConfig cfg_;
  LidarSpec spec_;
  std::uint64_t seed_;
  std::vector<float> cos_el_, sin_el_, cos_az_, sin_az_;
};

/// Pose at fraction f of the way from a to b (translation linear, rotation slerp).
Pose3 interpolatePose(const Pose3& a, const Pose3& b, double f);
/// Pose of a trajectory at time t >= traj[i].t: interpolated between the poses around t; the last
/// pose beyond the trajectory's end. (Where a point fired at t was seen from.)
Pose3 poseAtTime(const Trajectory& traj, std::size_t i, double t);
/// Where the sensor is one sweep period after pose i: poseAtTime(traj, i, traj[i].t + period_s).
inline Pose3 sweepEndPose(const Trajectory& traj, std::size_t i, double period_s) {
  return poseAtTime(traj, i, traj.at(i).t + period_s);
}

}  // namespace slamroute::simulate
