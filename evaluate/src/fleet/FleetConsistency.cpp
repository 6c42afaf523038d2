// Pairwise consistency of inter-vehicle closures: every closure implies where vehicle b's
// estimate lies in vehicle a's frame; a look-alike place implies somewhere else than the rest.
#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "FleetInternal.hpp"

namespace slamroute::evaluate {
namespace {

const FleetKeyframe& kfOf(const std::vector<std::vector<FleetKeyframe>>& kfs, int v, int k) {
  return kfs[static_cast<std::size_t>(v)][static_cast<std::size_t>(k)];
}

/// Where closure c puts vehicle b's keyframe of closure `other` (a's frame).
Eigen::Vector3d predicted(const FleetClosure& c, const FleetClosure& other,
                          const std::vector<std::vector<FleetKeyframe>>& kfs) {
  const Pose3 correction = kfOf(kfs, c.vehicle_a, c.keyframe_a).pose * c.T_a_b *
                           kfOf(kfs, c.vehicle_b, c.keyframe_b).pose.inverse();
  return (correction * kfOf(kfs, other.vehicle_b, other.keyframe_b).pose).translation();
}

/// Path between two closures, summed over both vehicles [m].
double pathBetween(const FleetClosure& i, const FleetClosure& j,
                   const std::vector<std::vector<FleetKeyframe>>& kfs) {
  return std::abs(kfOf(kfs, i.vehicle_a, i.keyframe_a).distance_m -
                  kfOf(kfs, j.vehicle_a, j.keyframe_a).distance_m) +
         std::abs(kfOf(kfs, i.vehicle_b, i.keyframe_b).distance_m -
                  kfOf(kfs, j.vehicle_b, j.keyframe_b).distance_m);
}

bool agree(const FleetClosure& i, const FleetClosure& j, double path,
           const std::vector<std::vector<FleetKeyframe>>& kfs, const FleetMergeOptions& opt) {
  const Eigen::Vector3d own = (kfOf(kfs, j.vehicle_a, j.keyframe_a).pose * j.T_a_b).translation();
  return (predicted(i, j, kfs) - own).norm() <= opt.consistency_m + opt.consistency_per_m * path;
}

/// Whether closure i agrees with most of its neighbours (idx: its pair's closures).
bool supported(std::size_t i, const std::vector<std::size_t>& idx,
               const std::vector<FleetClosure>& closures,
               const std::vector<std::vector<FleetKeyframe>>& kfs, const FleetMergeOptions& opt) {
  int neighbours = 0, support = 0;
  for (std::size_t j : idx) {
    const double path = pathBetween(closures[i], closures[j], kfs);
    if (path > opt.consistency_window_m) continue;
    ++neighbours;
    support += agree(closures[i], closures[j], path, kfs, opt) ? 1 : 0;
  }
  return 2 * support > neighbours && support >= opt.min_pair_closures;
}

}  // namespace

std::vector<FleetClosure> consistentClosures(const std::vector<FleetClosure>& closures,
                                             const std::vector<std::vector<FleetKeyframe>>& kfs,
                                             const FleetMergeOptions& opt) {
  std::map<std::pair<int, int>, std::vector<std::size_t>> by_pair;
  for (std::size_t i = 0; i < closures.size(); ++i)
    by_pair[{closures[i].vehicle_a, closures[i].vehicle_b}].push_back(i);
  std::vector<bool> keep(closures.size(), false);
  for (const auto& [pair, idx] : by_pair)
    for (std::size_t i : idx) keep[i] = supported(i, idx, closures, kfs, opt);
  std::vector<FleetClosure> out;
  for (std::size_t i = 0; i < closures.size(); ++i)
    if (keep[i]) out.push_back(closures[i]);
  return out;
}

}  // namespace slamroute::evaluate
