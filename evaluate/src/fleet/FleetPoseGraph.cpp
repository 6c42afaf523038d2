// One pose graph over the keyframes of every vehicle: each vehicle's chain of keyframes (its own
// SLAM's relative motion), the inter-vehicle closures, and a weak prior holding each vehicle's
// first keyframe where its estimate put it relative to vehicle 0's (a vehicle without closures
// stays as it was instead of floating). Every pose then moves with its neighbouring keyframes.
#include <algorithm>
#include <cmath>

#include "FleetInternal.hpp"
#include "slamroute/evaluate/PoseGraph.hpp"

namespace slamroute::evaluate {
namespace {

std::vector<int> nodeOffsets(const std::vector<std::vector<FleetKeyframe>>& kfs) {
  std::vector<int> off = {0};
  for (const auto& k : kfs) off.push_back(off.back() + static_cast<int>(k.size()));
  return off;
}

std::vector<PoseGraphEdge> graphEdges(const std::vector<std::vector<FleetKeyframe>>& kfs,
                                      const std::vector<int>& off,
                                      const std::vector<FleetClosure>& closures, const Config& cfg,
                                      const FleetMergeOptions& opt) {
  std::vector<PoseGraphEdge> edges;
  for (std::size_t v = 0; v < kfs.size(); ++v) {
    for (std::size_t k = 1; k < kfs[v].size(); ++k) {
      const Pose3 rel = kfs[v][k - 1].pose.inverse() * kfs[v][k].pose;
      // the SLAM's odometry sigma holds per metre of keyframe spacing; steps add up as a walk
      const double steps = std::max(1.0, std::sqrt(rel.translation().norm()));
      edges.push_back({off[v] + static_cast<int>(k) - 1, off[v] + static_cast<int>(k), rel,
                       cfg.loop.graph_odom_sigma_m * steps, cfg.loop.graph_odom_sigma_rad * steps});
    }
    if (v > 0)
      edges.push_back({0, off[v], kfs[0][0].pose.inverse() * kfs[v][0].pose, opt.start_sigma_m,
                       opt.start_sigma_rad});
  }
  for (const auto& c : closures)
    edges.push_back({off[static_cast<std::size_t>(c.vehicle_a)] + c.keyframe_a,
                     off[static_cast<std::size_t>(c.vehicle_b)] + c.keyframe_b, c.T_a_b,
                     cfg.loop.graph_loop_sigma_m, cfg.loop.graph_loop_sigma_rad,
                     opt.closure_cauchy_sigmas});
  return edges;
}

/// T_world_world' that moves keyframe k: new * old^-1.
Pose3 correction(const FleetKeyframe& kf, const Pose3& moved) { return moved * kf.pose.inverse(); }

Pose3 blend(const Pose3& a, const Pose3& b, double s) {
  Pose3 out = Pose3::Identity();
  out.linear() = Eigen::Quaterniond(a.rotation())
                     .slerp(s, Eigen::Quaterniond(b.rotation()))
                     .toRotationMatrix();
  out.translation() = (1.0 - s) * a.translation() + s * b.translation();
  return out;
}

/// The estimate moved by the keyframes' corrections, interpolated in time between them.
Trajectory moveWithKeyframes(const Trajectory& est, const std::vector<FleetKeyframe>& kfs,
                             const std::vector<Pose3>& moved) {
  std::vector<Pose3> corr;
  for (std::size_t k = 0; k < kfs.size(); ++k) corr.push_back(correction(kfs[k], moved[k]));
  Trajectory out = est;
  std::size_t k = 0;
  for (auto& p : out) {
    while (k + 1 < kfs.size() && kfs[k + 1].t <= p.t) ++k;
    Pose3 c = corr[k];
    if (k + 1 < kfs.size() && p.t > kfs[k].t)
      c = blend(corr[k], corr[k + 1], (p.t - kfs[k].t) / (kfs[k + 1].t - kfs[k].t));
    p.T_world_body = c * p.T_world_body;
  }
  return out;
}

}  // namespace

std::vector<Trajectory> mergeFleetTrajectories(const std::vector<FleetVehicleInput>& vehicles,
                                               const std::vector<std::vector<FleetKeyframe>>& kfs,
                                               const std::vector<FleetClosure>& closures,
                                               const Config& cfg, const FleetMergeOptions& opt) {
  const std::vector<int> off = nodeOffsets(kfs);
  std::vector<Pose3> poses;
  for (const auto& k : kfs)
    for (const auto& kf : k) poses.push_back(kf.pose);
  optimizePoseGraph(poses, graphEdges(kfs, off, closures, cfg, opt), 0);
  std::vector<Trajectory> out;
  for (std::size_t v = 0; v < vehicles.size(); ++v) {
    const std::vector<Pose3> moved(poses.begin() + off[v], poses.begin() + off[v + 1]);
    out.push_back(moveWithKeyframes(vehicles[v].estimate, kfs[v], moved));
  }
  return out;
}

}  // namespace slamroute::evaluate
