#include "Relocaliser.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "slamroute/core/Log.hpp"

namespace slamroute::evaluate::slam {
namespace {

std::vector<Pose3> hypotheses(const Pose3& pred, bool have_velocity, double yaw_step_deg) {
  std::vector<Pose3> hyp;  // hyp[0] is the prediction
  if (have_velocity) {
    const double step = std::max(1.0, yaw_step_deg);
    const int n = static_cast<int>(std::floor(360.0 / step + 1e-9));
    for (int k = 0; k < n; ++k) {
      Pose3 h = pred;
      h.linear() =
          pred.rotation() *
          Eigen::AngleAxisd(k * step * std::numbers::pi / 180.0, Vec3::UnitZ()).toRotationMatrix();
      hyp.push_back(h);
    }
  } else {
    for (int k : {0, -1, 1, -2, 2, -3, 3, -4, 4})
      hyp.push_back(pred * Eigen::Translation3d(k * 1.0, 0.0, 0.0));
  }
  return hyp;
}

}  // namespace

std::optional<Relocalisation> relocalise(const FeatureMap& local_map, const PreparedScan& scan,
                                         const Pose3& pred, bool have_velocity,
                                         const AlignOptions& fine, int failed_inliers,
                                         const Config& cfg) {
  const RelocaliseConfig& c = cfg.relocalise;
  const int cap = std::max(50, c.max_points);
  const Cloud edges = capped(scan.src_edges, cap / 4), planes = capped(scan.src_planes, cap);
  // The search is for where the prediction went wrong: no prior may pull a hypothesis back to it.
  AlignOptions unpulled = fine;
  unpulled.prior_weight.setZero();
  AlignOptions coarse = unpulled;
  coarse.degenerate_eig = 0;
  coarse.iterations = c.iterations;
  const std::vector<Pose3> hyp = hypotheses(pred, have_velocity, c.yaw_step_deg);
  int inl_ref = 0, best_inl = -1;
  Pose3 best_T = pred;
  std::size_t best = 0;
  for (std::size_t k = 0; k < hyp.size(); ++k) {
    const AlignResult r = alignFeatures(local_map, edges, planes, hyp[k], coarse);
    if (k == 0) inl_ref = r.inliers;
    if (r.inliers > best_inl) {
      best_inl = r.inliers;
      best_T = r.T_target_source;
      best = k;
    }
  }
  // Another hypothesis must clearly beat the prediction; the prediction's own coarse result
  // (wider basin than the failed registration) must beat that registration's inliers.
  if (best != 0 && best_inl < 1.5 * inl_ref + 20) return std::nullopt;
  const AlignResult m = alignFeatures(local_map, scan.src_edges, scan.src_planes, best_T, unpulled);
  if (!enoughMatches(m, cfg.mapping)) return std::nullopt;
  if (best == 0 && m.inliers < 1.5 * failed_inliers + 20) return std::nullopt;
  logDebug("relocalised: inliers " + std::to_string(best_inl) + " vs " + std::to_string(inl_ref));
  return Relocalisation{m.T_target_source, m.inliers};
}

}  // namespace slamroute::evaluate::slam
