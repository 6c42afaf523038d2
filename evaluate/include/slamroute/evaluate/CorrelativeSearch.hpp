#pragma once
// Correlative scan matching in the ground plane (Olson 2009, "Real-time correlative scan
// matching"; the loop-closure search of Hess et al. 2016): every x / y offset and yaw of a search
// window is scored against a likelihood grid of the target, coarse blocks first with an upper
// bound so that only promising blocks are scored finely. Besides the best pose it reports the best
// score of any pose well away from it, so a caller can refuse a match that a look-alike place
// (a row of similar facades one period along the street) fits nearly as well. Local ICP cannot
// tell these apart: it settles in whichever minimum is nearest to where it starts.
#include <vector>

#include "slamroute/core/Types.hpp"
#include "slamroute/evaluate/Features.hpp"

namespace slamroute::evaluate {

struct CorrelativeOptions {
  double resolution_m = 0.25;    ///< fine grid cell and offset step [m]
  int coarse_cells = 4;          ///< a coarse block is this many fine cells a side
  double sigma_m = 0.3;          ///< likelihood of a source point: exp(-d^2 / 2 sigma^2) [m]
  double window_m = 10.0;        ///< offsets within +-window_m in x and y of the start [m]
  double yaw_window_rad = 0.07;  ///< yaws within +-this of the start's [rad]
  double yaw_step_rad = 0.0175;  ///< yaw step [rad]
  double separation_m = 2.0;     ///< the runner-up is the best pose at least this far away [m]
  /// Blocks whose bound is below this share of the best score are not scored finely: the
  /// runner-up is exact when it reaches this share, otherwise reported as below it.
  double prune_share = 0.7;
  int max_source_points = 800;  ///< source points scored (strided) [1]
  void validate() const;
};

struct CorrelativeResult {
  Pose3 best = Pose3::Identity();  ///< the start moved by the best offset and yaw
  double score = 0.0;              ///< mean likelihood of the source points there, 0..1
  /// The best score of a pose at least separation_m from the best (at most prune_share x score
  /// when none reaches that share).
  double runner_up = 0.0;
  Vec3 runner_up_offset = Vec3::Zero();  ///< that pose's offset from the best [m]
  int source_points = 0;
};

/// Scores `source` (points in its body frame, already reduced to the structure worth matching)
/// placed at `start` moved by every offset and yaw of the window against `target` (world frame),
/// in x / y only: heights and roll / pitch stay those of `start`.
CorrelativeResult correlativeSearch(const Cloud& target, const Cloud& source, const Pose3& start,
                                    const CorrelativeOptions& o);

/// Points of `cloud` (in the frame of `body`) whose height above the road under the sensor lies in
/// [min_above_road_m, max_above_road_m]: walls, poles, parked cars and trees, without the ground
/// that matches everywhere.
Cloud structureAboveRoad(const Cloud& cloud, double sensor_height_m, double min_above_road_m,
                         double max_above_road_m);

}  // namespace slamroute::evaluate
