#pragma once
// Loop closure (paper §3.3 / LeGO-LOAM): a new keyframe near an old one (in the estimate) is
// matched by ICP against the old keyframe's submap; the match must fit, must not be a local
// minimum along a row of look-alikes, and must be a correction the odometry can have drifted;
// then a loop edge joins the pose graph.
#include <optional>
#include <vector>

#include "KeyframeGraph.hpp"
#include "slamroute/evaluate/Config.hpp"
#include "slamroute/evaluate/Registration.hpp"
#include "slamroute/evaluate/Slam.hpp"

namespace slamroute::evaluate::slam {

struct LoopStats {
  std::vector<LoopClosure> loops;  ///< accepted
  int candidates = 0;              ///< ICP attempts
  int rejected = 0;                ///< refused for too large a correction
  int ambiguous = 0;               ///< refused: ICP from nearby starts fits better elsewhere
};

class LoopCloser {
 public:
  explicit LoopCloser(const Config& cfg) : cfg_(cfg) {}
  /// Tries to close a loop from the newest keyframe; true when a closure was added (the graph
  /// is then re-optimised).
  bool tryClose(KeyframeGraph& graph, StageTimes& times);
  const LoopStats& stats() const { return stats_; }

 private:
  /// The old keyframe nearest to the newest one within loop.radius_m, old enough; -1 if none.
  int candidate(const KeyframeGraph& graph) const;
  /// ICP of the newest keyframe's cloud against the candidate's submap, with the checks; the
  /// match when it passes them.
  std::optional<IcpResult> verify(const KeyframeGraph& graph, int old_kf);
  void accept(KeyframeGraph& graph, int old_kf, const IcpResult& icp, StageTimes& times);

  const Config& cfg_;
  LoopStats stats_;
  double last_loop_t_ = -1e18, last_attempt_t_ = -1e18;
};

}  // namespace slamroute::evaluate::slam
