#pragma once
// C_k, the predicted pose uncertainty the coverage planners bound (paper eqs. 1-3).
//
// C_k = ||Sigma_xy||_0, the D-optimality criterion (eq. 3 with p = 0) of the EIF's 2x2 position
// covariance after the k-th driven edge: exp(mean log eigenvalue) = sqrt(det Sigma_xy), in m^2
// (the variance of a circle with the same area as the error ellipse). Driving raises it (the
// EIF prediction, Eif.hpp); arriving at a mapped node after at least eif.loop_min_travel_m of
// driving since the last visit there closes a loop that re-anchors the pose to the map there:
// the covariance becomes the place's stored one plus the registration noise R_lc, when that is
// smaller (det). Unlike PoseEif::closeLoop (independent fusion) this keeps the correlation of a
// drive with its own recent map: re-seeing a street mapped a minute ago with the same drift
// does not shrink the drift. C_k drops to about the C the place was mapped with. That is eq. 1's
// reset to eps_0 at a loop-closure node, with eps_0 the place's own uncertainty instead of 0.
// The bound is C_k <= C_threshold at every step (eq. 2 sums C over the route; a per-step bound
// is what "the filter diverges above an acceptable uncertainty", §3.1, needs).
#include <memory>
#include <vector>

#include "slamroute/rl/Config.hpp"
#include "slamroute/rl/Eif.hpp"
#include "slamroute/rl/PlanGraph.hpp"

namespace slamroute::rl {

/// D-optimality of the position block of a pose covariance [m^2].
double positionDOptimality(const Eigen::Matrix3d& cov);

using EdgeMotions = std::shared_ptr<const std::vector<EdgeMotion>>;
/// The EIF motion model of every edge of pg, computed once and shared by trackers.
EdgeMotions edgeMotions(const PlanGraph& pg, const EifConfig& cfg);

/// C_k along a route, step by step: the EIF's prediction (same F, Q and R_lc as PoseEif) kept in
/// covariance form, which needs no matrix inverse per step. Copyable (the switching planner looks
/// ahead on a copy).
class UncertaintyTracker {
 public:
  UncertaintyTracker(const PlanGraph& pg, const EifConfig& cfg, int start, EdgeMotions motions);
  /// Drives local edge e (leaving the current node); returns C_k after it.
  double drive(int e);
  double c() const { return c_; }
  double travelledM() const { return travelled_m_; }
  bool mapped(int node) const { return mapped_[static_cast<std::size_t>(node)] != 0; }
  /// C_k stored at a mapped node: the best (lowest) it was seen with.
  double placeC(int node) const { return place_c_[static_cast<std::size_t>(node)]; }
  /// Driving since the last visit of a mapped node [m].
  double sinceVisitM(int node) const {
    return travelled_m_ - last_visit_m_[static_cast<std::size_t>(node)];
  }
  int closures() const { return closures_; }

 private:
  const PlanGraph* pg_;
  const EifConfig* cfg_;
  EdgeMotions motions_;
  Eigen::Matrix3d cov_, r_lc_;
  std::vector<Eigen::Matrix3d> node_cov_;
  std::vector<double> place_c_, last_visit_m_;
  std::vector<char> mapped_;
  double travelled_m_ = 0.0, c_ = 0.0;
  int closures_ = 0;
};

struct UncertaintySeries {
  std::vector<double> c_m2;  ///< C_k after each driven edge [m^2]
  double max_m2 = 0.0, mean_m2 = 0.0;
  int closures = 0;
};

/// C_k along a local edge sequence from `start`.
UncertaintySeries predictUncertainty(const PlanGraph& pg, const EifConfig& cfg, int start,
                                     const std::vector<int>& edges);

}  // namespace slamroute::rl
