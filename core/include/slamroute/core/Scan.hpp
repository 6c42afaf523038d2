#pragma once
// LiDAR scans and the scan-source interface the evaluator reads from. A drive either saves
// scans as KITTI .bin files (KittiScanSource) or lets the simulator regenerate them on demand
// (simulate::SimulatedScanSource); the evaluator sees only ScanSource.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace slamroute {

/// Geometry of a spinning multi-beam LiDAR.
struct LidarSpec {
  int channels = 64;              ///< rings
  double vfov_up_deg = 10.0;      ///< upper edge of the vertical field [deg]
  double vfov_down_deg = -30.0;   ///< lower edge [deg]
  int horizontal_samples = 1800;  ///< azimuth steps per revolution
  double max_range_m = 100.0;
  double min_range_m = 1.0;
  double mount_height_m = 1.8;  ///< sensor above the road [m]
};
template <class V>
void visitFields(V& v, LidarSpec& c) {
  v.field("channels", c.channels, "rings");
  v.field("vfov_up_deg", c.vfov_up_deg, "upper edge of vertical field [deg]");
  v.field("vfov_down_deg", c.vfov_down_deg, "lower edge of vertical field [deg]");
  v.field("horizontal_samples", c.horizontal_samples, "azimuth steps per revolution");
  v.field("max_range_m", c.max_range_m, "max range [m]");
  v.field("min_range_m", c.min_range_m, "min range [m]");
  v.field("mount_height_m", c.mount_height_m, "sensor height above road [m]");
}
/// Named presets: "paper" (64 ch, +10/-30 deg, 100 m), "vlp16", "hdl32". Throws on unknown.
LidarSpec lidarPreset(const std::string& name);

struct ScanPoint {
  float x = 0, y = 0, z = 0;  ///< sensor frame at the point's own firing time [m]
  float intensity = 0;
  int ring = -1;  ///< -1 when unknown (e.g. read from KITTI .bin)
  float dt = 0;   ///< firing time after Scan::t [s] (0 for an instantaneous scan)
};
struct Scan {
  double t = 0.0;  ///< time of the sweep's start: the frame the scan is deskewed to [s]
  std::vector<ScanPoint> points;
  bool has_point_times = false;  ///< the points carry their firing times (ScanPoint::dt)
};

class ScanSource {
 public:
  virtual ~ScanSource() = default;
  virtual std::size_t size() const = 0;
  virtual double time(std::size_t i) const = 0;
  /// Throws std::runtime_error naming the scan when it cannot be produced (missing file, …).
  virtual Scan scan(std::size_t i) const = 0;
  virtual LidarSpec spec() const = 0;
};

/// KITTI velodyne layout: DIR/NNNNNN.bin (float32 x,y,z,intensity) + DIR/times.txt. A scan with
/// point times also gets DIR/NNNNNN.time beside its .bin: one float32 per point, the point's
/// firing time after the scan's entry in times.txt [s]. Readers that know only KITTI ignore it.
void writeKittiScan(const std::filesystem::path& path, const Scan& scan);
/// Reads NNNNNN.bin and, when it exists, NNNNNN.time beside it (point count must match).
Scan readKittiScan(const std::filesystem::path& path);
/// The point-time file that belongs to a KITTI .bin path (NNNNNN.time).
std::filesystem::path kittiPointTimesPath(const std::filesystem::path& bin_path);

class KittiScanSource : public ScanSource {
 public:
  /// `dir` holds NNNNNN.bin and times.txt. Ring indices are recovered from the elevation angle.
  KittiScanSource(std::filesystem::path dir, LidarSpec spec);
  /// The same with the times in another file (a KITTI odometry sequence keeps times.txt beside
  /// its velodyne/ folder).
  KittiScanSource(std::filesystem::path dir, LidarSpec spec, const std::filesystem::path& times);
  std::size_t size() const override { return times_.size(); }
  double time(std::size_t i) const override { return times_.at(i); }
  Scan scan(std::size_t i) const override;
  LidarSpec spec() const override { return spec_; }

 private:
  std::filesystem::path dir_;
  LidarSpec spec_;
  std::vector<double> times_;
};

/// Ring index of a point from its elevation angle for a sensor with evenly spaced beams.
int ringFromElevation(const LidarSpec& spec, double x, double y, double z);

}  // namespace slamroute
