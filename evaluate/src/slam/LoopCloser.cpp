#include "LoopCloser.hpp"

#include <algorithm>
#include <string>

#include "SlamClock.hpp"
#include "slamroute/core/Log.hpp"
#include "slamroute/evaluate/MotionChecks.hpp"

namespace slamroute::evaluate::slam {

bool LoopCloser::tryClose(KeyframeGraph& graph, StageTimes& times) {
  const double t = graph.back().t;
  if (t - last_loop_t_ < cfg_.loop.cooldown_s || t - last_attempt_t_ < 1.0) return false;
  const int old_kf = candidate(graph);
  if (old_kf < 0) return false;
  last_attempt_t_ = t;
  ++stats_.candidates;
  const std::optional<IcpResult> icp = verify(graph, old_kf);
  if (!icp) return false;
  accept(graph, old_kf, *icp, times);
  return true;
}

int LoopCloser::candidate(const KeyframeGraph& graph) const {
  const Keyframe& cur = graph.back();
  int best = -1;
  double best_d = cfg_.loop.radius_m;
  for (std::size_t k = 0; k + 1 < graph.size(); ++k) {
    const Keyframe& kf = graph.at(k);
    if (cur.t - kf.t < cfg_.loop.min_time_gap_s) break;  // keyframes are in time order
    const double d = (kf.T_world.translation() - cur.T_world.translation()).norm();
    if (d < best_d) {
      best_d = d;
      best = static_cast<int>(k);
    }
  }
  return best;
}

std::optional<IcpResult> LoopCloser::verify(const KeyframeGraph& graph, int old_kf) {
  const LoopConfig& c = cfg_.loop;
  const Keyframe& cur = graph.back();
  const int n = static_cast<int>(graph.size());
  Cloud target;
  for (int k = std::max(0, old_kf - c.submap_keyframes); k <= std::min(n - 2, old_kf + c.submap_keyframes); ++k) {
    const Keyframe& kf = graph.at(static_cast<std::size_t>(k));
    if (cur.t - kf.t < c.min_time_gap_s) continue;
    const Cloud moved = transformed(graph.clouds().get(kf.cloud), kf.T_world);
    target.insert(target.end(), moved.begin(), moved.end());
  }
  const IcpTarget icp_target(voxelFilter(target, c.voxel_m));
  const Cloud source = voxelFilter(graph.clouds().get(cur.cloud), c.voxel_m);
  const IcpResult icp = icp_target.align(source, cur.T_world, c.icp_iterations, c.icp_max_corr_m);
  logDebug("loop candidate kf " + std::to_string(old_kf) + " -> " + std::to_string(n - 1) + ": fitness " +
           std::to_string(icp.fitness_m2) + " inliers " + std::to_string(icp.inlier_ratio));
  const IcpAcceptance accept{c.fitness_m2, c.min_inlier_ratio};
  if (!accept(icp)) return std::nullopt;
  const IcpAmbiguity amb{c.ambiguity_along_m,      c.ambiguity_across_m, c.ambiguity_separation_m,
                         c.ambiguity_inlier_margin, c.icp_iterations,     c.icp_max_corr_m,
                         accept};
  if (const auto other = betterIcpMatch(icp_target, source, icp, amb)) {
    ++stats_.ambiguous;
    logDebug("loop candidate refused: a match " + std::to_string(*other) + " m away fits better");
    return std::nullopt;
  }
  const double correction = (icp.T_target_source.translation() - cur.T_world.translation()).norm();
  if (!plausibleLoopCorrection(correction, graph.drivenSinceLoop(), cfg_)) {
    ++stats_.rejected;
    logDebug("loop candidate rejected: correction " + std::to_string(correction) + " m after " +
             std::to_string(graph.drivenSinceLoop()) + " m");
    return std::nullopt;
  }
  return icp;
}

void LoopCloser::accept(KeyframeGraph& graph, int old_kf, const IcpResult& icp, StageTimes& times) {
  const Keyframe& old = graph.at(static_cast<std::size_t>(old_kf));
  const Keyframe& cur = graph.back();
  const int n = static_cast<int>(graph.size());
  PoseGraphEdge e;
  e.from = old_kf;
  e.to = n - 1;
  e.T_from_to = old.T_world.inverse() * icp.T_target_source;
  e.sigma_m = cfg_.loop.graph_loop_sigma_m;
  e.sigma_rad = cfg_.loop.graph_loop_sigma_rad;
  const double correction = (icp.T_target_source.translation() - cur.T_world.translation()).norm();
  stats_.loops.push_back({old_kf, n - 1, old.t, cur.t, icp.fitness_m2, correction, e.T_from_to});
  last_loop_t_ = cur.t;
  const double t_cur = cur.t;
  const double t0 = cpuNow();
  graph.closeLoop(e);
  times.pose_graph += cpuSince(t0);
  logInfo("loop closure: keyframe " + std::to_string(n - 1) + " (t=" + std::to_string(t_cur) +
          " s) matches keyframe " + std::to_string(old_kf) + ", fitness " + std::to_string(icp.fitness_m2) +
          " m^2");
}

}  // namespace slamroute::evaluate::slam
