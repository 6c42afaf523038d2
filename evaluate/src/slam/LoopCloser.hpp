#pragma once
// Loop closure (paper §3.3 / LeGO-LOAM): a new keyframe near an old one in the estimate, or, when
// none is, one whose place descriptor matches within a drift gate, is matched by ICP against the
// old keyframe's submap; the match must fit, must not be a local minimum along a row of
// look-alikes, and must be a correction the odometry can have drifted, consistent with the closure
// before it; then a loop edge joins the pose graph.
#include <optional>
#include <vector>

#include "KeyframeGraph.hpp"
#include "slamroute/evaluate/Config.hpp"
#include "slamroute/evaluate/PlaceDatabase.hpp"
#include "slamroute/evaluate/Registration.hpp"
#include "slamroute/evaluate/Slam.hpp"

namespace slamroute::evaluate::slam {

struct LoopStats {
  std::vector<LoopClosure> loops;  ///< accepted
  int candidates = 0;              ///< ICP attempts
  /// refused for a correction the odometry cannot have drifted: beyond a place candidate's gate,
  /// loop.max_correction_m, or breaking the cycle with the closure before (ClosureCycle.hpp)
  int rejected = 0;
  /// refused: ICP from nearby starts fits as well elsewhere, a corridor, or a submap whose sides
  /// put the new keyframe apart
  int ambiguous = 0;
};

/// An old keyframe the newest one may revisit, and where its ICP starts.
struct LoopCandidate {
  int keyframe = -1;
  Pose3 init = Pose3::Identity();  ///< ICP start: the estimate, or the old pose turned by the yaw
  std::optional<PlaceCandidate> place;  ///< set when the descriptor proposed it
  double gate_m = 0.0;                  ///< a place candidate's correction must stay within [m]
};

class LoopCloser {
 public:
  /// `sensor_height_m`: the LiDAR above the road (the place descriptor counts heights from it).
  LoopCloser(const Config& cfg, double sensor_height_m)
      : cfg_(cfg), sensor_height_m_(sensor_height_m), places_(cfg.loop.place) {}
  /// Whether descriptor candidates are sought (LiDAR-only runs: with wheel odometry + gyro the
  /// estimate stays within loop.radius_m of a revisit, and a descriptor match farther away is a
  /// look-alike place).
  void setPlaceSearch(bool on) { place_search_ = on; }
  /// Describes the newest keyframe's place from its segmented cloud (body frame).
  void addPlace(const KeyframeGraph& graph, const Cloud& segmented_body);
  /// Tries to close a loop from the newest keyframe; true when a closure was added (the graph
  /// is then re-optimised).
  bool tryClose(KeyframeGraph& graph, StageTimes& times);
  const LoopStats& stats() const { return stats_; }

 private:
  /// The old keyframe nearest to the newest one within loop.radius_m of the estimate, on its level.
  std::optional<LoopCandidate> nearbyCandidate(const KeyframeGraph& graph) const;
  /// The best descriptor match among old keyframes within the drift gate, on its level.
  std::optional<LoopCandidate> placeCandidate(const KeyframeGraph& graph) const;
  /// ICP of the newest keyframe's cloud against the candidate's submap, with the checks; the
  /// match when it passes them.
  std::optional<IcpResult> verify(const KeyframeGraph& graph, const LoopCandidate& c);
  /// The match, or the rival that fits better than it, when that pins the new keyframe down: no
  /// other start fits as well, the matched planes hold it along the street, and each side of the
  /// candidate's submap puts it where the whole does (a rival taken needs one side matched alone:
  /// submapBacks).
  std::optional<IcpResult> pinDown(const KeyframeGraph& graph, int old_kf, const IcpTarget& target,
                                   const Cloud& source, const IcpResult& icp) const;
  /// The match closes the cycle with the last accepted closure (ClosureCycle.hpp); no closure
  /// yet counts as consistent.
  bool consistentWithLastClosure(const KeyframeGraph& graph, int old_kf,
                                 const IcpResult& icp) const;
  /// Half-width of the square searched around the estimate: grows with the path since the last
  /// closure (the drift it may have brought) [m].
  double searchWindow(const KeyframeGraph& graph) const;
  /// The clouds of the candidate's keyframes each side, in the world frame; `structure_only`:
  /// without the ground.
  Cloud submap(const KeyframeGraph& graph, int old_kf, bool structure_only) const;
  /// The clouds of keyframes first..last old enough to be candidates, in the world frame.
  Cloud keyframeClouds(const KeyframeGraph& graph, int first, int last, bool structure_only) const;
  Cloud structureOf(const Cloud& body) const;
  /// The points within range_m of centre in x / y.
  static Cloud within(const Cloud& cloud, const Vec3& centre, double range_m);
  /// The best pose of the correlative search over the window, unless a pose elsewhere in it
  /// scores nearly as well (a look-alike stretch of street).
  std::optional<Pose3> uniqueStart(const KeyframeGraph& graph, const LoopCandidate& cand);

  /// Structure that tells places apart: above kerbs and bonnets, below where the sensor sees [m].
  static constexpr double kStructureMinM = 0.4, kStructureMaxM = 10.0;
  /// The correlative search scores the source points within this range (where both scans see
  /// the same structure densely enough) against the target within it plus the window [m].
  static constexpr double kMatchRangeM = 40.0;
  void accept(KeyframeGraph& graph, const LoopCandidate& c, const IcpResult& icp,
              StageTimes& times);

  const Config& cfg_;
  double sensor_height_m_;
  PlaceDatabase places_;
  PlaceDescriptor newest_;  ///< the newest described keyframe's descriptor
  int newest_kf_ = -1;      ///< ... and its index
  bool place_search_ = true;
  LoopStats stats_;
  double last_loop_t_ = -1e18, last_attempt_t_ = -1e18;
};

}  // namespace slamroute::evaluate::slam
