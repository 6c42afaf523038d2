#pragma once
// Where evaluate puts the SLAM's map as it comes, tile by tile (MapTiles.hpp): map.pcd and, with
// the world mesh, the map's accuracy twice (as built, in the frame the estimate starts in, and
// after the rigid alignment of the estimate onto the ground truth that the ATE uses, which
// leaves only the map's own deformation) and the aligned map's top view (MapErrorImage).
#include <filesystem>
#include <optional>

#include "slamroute/core/Trajectory.hpp"
#include "slamroute/evaluate/MapAccuracy.hpp"
#include "slamroute/evaluate/MapTiles.hpp"
#include "slamroute/evaluate/Output.hpp"

namespace slamroute::evaluate {

class MapOutput : public MapSink {
 public:
  /// `mesh` and `gt` may be null (no accuracy, no alignment); both must outlive this object.
  /// `max_dt_s`: pose association tolerance of the alignment; `max_m`: the distance clamp.
  MapOutput(const std::filesystem::path& pcd, const Mesh* mesh, const Trajectory* gt,
            double max_dt_s, double max_m, int image_px);
  void estimate(const Trajectory& est) override;
  void begin(const Eigen::AlignedBox3f& bounds) override;
  void add(const Cloud& part) override;
  /// Writes map.pcd.
  void commit();
  /// T_gt_est of the estimate the map was built on (identity before estimate() or without gt).
  const Pose3& alignment() const { return T_gt_est_; }
  /// The map's accuracy as built and aligned (none without a mesh).
  std::optional<MapAccuracy> accuracy() const;
  std::optional<MapAccuracy> alignedAccuracy() const;
  /// Writes the aligned map's top view coloured by distance to the world surface (mesh only).
  void writeImage(const std::filesystem::path& png) const;

 private:
  PcdWriter pcd_;
  const Mesh* mesh_;
  const Trajectory* gt_;
  double max_dt_s_, max_m_;
  int image_px_;
  Pose3 T_gt_est_ = Pose3::Identity();
  std::optional<MapAccuracyMeter> built_, aligned_;
  std::optional<MapErrorImage> image_;
};

}  // namespace slamroute::evaluate
