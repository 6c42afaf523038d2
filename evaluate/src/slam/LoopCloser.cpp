#include "LoopCloser.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "ClosureCycle.hpp"
#include "SlamClock.hpp"
#include "slamroute/core/Log.hpp"
#include "slamroute/evaluate/CorrelativeSearch.hpp"
#include "slamroute/evaluate/LoopVerification.hpp"
#include "slamroute/evaluate/MotionChecks.hpp"
#include "slamroute/evaluate/SubmapAgreement.hpp"

namespace slamroute::evaluate::slam {

void LoopCloser::addPlace(const KeyframeGraph& graph, const Cloud& segmented_body) {
  if (!cfg_.loop.enabled || !cfg_.loop.place_recognition || !place_search_) return;
  newest_ = makePlaceDescriptor(segmented_body, sensor_height_m_, cfg_.loop.place);
  newest_kf_ = static_cast<int>(graph.size()) - 1;
  places_.add(newest_kf_, newest_, graph.back().T_world.translation());
}

bool LoopCloser::tryClose(KeyframeGraph& graph, StageTimes& times) {
  const double t = graph.back().t;
  if (t - last_loop_t_ < cfg_.loop.cooldown_s || t - last_attempt_t_ < 1.0) return false;
  std::optional<LoopCandidate> c = nearbyCandidate(graph);  // the estimate: same place
  if (!c && cfg_.loop.place_recognition && place_search_)
    c = placeCandidate(graph);  // the descriptor
  if (!c) return false;
  last_attempt_t_ = t;
  ++stats_.candidates;
  const std::optional<IcpResult> icp = verify(graph, *c);
  if (!icp) return false;
  accept(graph, *c, *icp, times);
  return true;
}

std::optional<LoopCandidate> LoopCloser::nearbyCandidate(const KeyframeGraph& graph) const {
  const Keyframe& cur = graph.back();
  std::optional<LoopCandidate> best;
  double best_d = searchWindow(graph);
  for (std::size_t k = 0; k + 1 < graph.size(); ++k) {
    const Keyframe& kf = graph.at(k);
    if (cur.t - kf.t < cfg_.loop.min_time_gap_s) break;  // keyframes are in time order
    if (!onSameLevel(kf.T_world.translation(), cur.T_world.translation(), cfg_.loop)) continue;
    const double d = (kf.T_world.translation() - cur.T_world.translation()).norm();
    if (d < best_d) {
      best_d = d;
      best = LoopCandidate{static_cast<int>(k), cur.T_world, std::nullopt, 0.0};
    }
  }
  return best;
}

std::optional<LoopCandidate> LoopCloser::placeCandidate(const KeyframeGraph& graph) const {
  const Keyframe& cur = graph.back();
  if (newest_kf_ != static_cast<int>(graph.size()) - 1) return std::nullopt;  // not described
  PlaceQuery q;
  q.newest_keyframe = -1;
  for (std::size_t k = 0; k + 1 < graph.size() && cur.t - graph.at(k).t >= cfg_.loop.min_time_gap_s;
       ++k)
    q.newest_keyframe = static_cast<int>(k);
  if (q.newest_keyframe < 0) return std::nullopt;
  const double gate =
      std::min(cfg_.loop.place_gate_max_m,
               cfg_.loop.radius_m + cfg_.loop.place_gate_per_m * graph.drivenSinceLoop());
  q.gate_centre = cur.T_world.translation();
  q.gate_radius_m = gate;
  const std::vector<PlaceCandidate> found = places_.query(newest_, q);
  const auto best_it = std::find_if(found.begin(), found.end(), [&](const PlaceCandidate& p) {
    return onSameLevel(graph.at(static_cast<std::size_t>(p.keyframe)).T_world.translation(),
                       cur.T_world.translation(), cfg_.loop);
  });
  if (best_it == found.end()) return std::nullopt;
  const PlaceCandidate& best = *best_it;
  Pose3 turn = Pose3::Identity();
  turn.linear() = Eigen::AngleAxisd(best.yaw_rad, Vec3::UnitZ()).toRotationMatrix();
  const Pose3 init = graph.at(static_cast<std::size_t>(best.keyframe)).T_world * turn;
  return LoopCandidate{best.keyframe, init, best, gate};
}

double LoopCloser::searchWindow(const KeyframeGraph& graph) const {
  const LoopConfig& c = cfg_.loop;
  if (!c.correlative) return c.radius_m;
  return std::min(c.window_max_m, c.radius_m + c.window_per_m * graph.drivenSinceLoop());
}

Cloud LoopCloser::submap(const KeyframeGraph& graph, int old_kf, bool structure_only) const {
  const int each_side = cfg_.loop.submap_keyframes;
  return keyframeClouds(graph, old_kf - each_side, old_kf + each_side, structure_only);
}

Cloud LoopCloser::keyframeClouds(const KeyframeGraph& graph, int first, int last,
                                 bool structure_only) const {
  const Keyframe& cur = graph.back();
  const int n = static_cast<int>(graph.size());
  Cloud out;
  for (int k = std::max(0, first); k <= std::min(n - 2, last); ++k) {
    const Keyframe& kf = graph.at(static_cast<std::size_t>(k));
    if (cur.t - kf.t < cfg_.loop.min_time_gap_s) continue;
    const Cloud& body = graph.clouds().get(kf.cloud);
    const Cloud moved = transformed(structure_only ? structureOf(body) : body, kf.T_world);
    out.insert(out.end(), moved.begin(), moved.end());
  }
  return out;
}

Cloud LoopCloser::within(const Cloud& cloud, const Vec3& centre, double range_m) {
  Cloud out;
  for (const auto& p : cloud)
    if ((p.cast<double>() - centre).head<2>().squaredNorm() <= range_m * range_m) out.push_back(p);
  return out;
}

Cloud LoopCloser::structureOf(const Cloud& body) const {
  return structureAboveRoad(body, sensor_height_m_, kStructureMinM, kStructureMaxM);
}

std::optional<Pose3> LoopCloser::uniqueStart(const KeyframeGraph& graph,
                                             const LoopCandidate& cand) {
  const LoopConfig& c = cfg_.loop;
  CorrelativeOptions o;
  o.window_m = searchWindow(graph);
  o.yaw_window_rad = c.correlative_yaw_deg * std::numbers::pi / 180.0;
  o.separation_m = c.correlative_separation_m;
  o.prune_share = std::min(o.prune_share, c.correlative_max_ratio);
  const Cloud source =
      within(structureOf(graph.clouds().get(graph.back().cloud)), Vec3::Zero(), kMatchRangeM);
  const Cloud target = within(submap(graph, cand.keyframe, true), cand.init.translation(),
                              kMatchRangeM + o.window_m);
  const CorrelativeResult r = correlativeSearch(target, source, cand.init, o);
  logDebug("loop candidate kf " + std::to_string(cand.keyframe) + ": correlative score " +
           std::to_string(r.score) + " rival " + std::to_string(r.runner_up) + " at " +
           std::to_string(r.runner_up_offset.norm()) + " m, window " + std::to_string(o.window_m) +
           " m, moved " + std::to_string((r.best.translation() - cand.init.translation()).norm()) +
           " m");
  if (r.runner_up >= c.correlative_max_ratio * r.score) return std::nullopt;
  return r.best;
}

std::optional<IcpResult> LoopCloser::verify(const KeyframeGraph& graph, const LoopCandidate& cand) {
  const LoopConfig& c = cfg_.loop;
  const int old_kf = cand.keyframe;
  const Keyframe& cur = graph.back();
  const int n = static_cast<int>(graph.size());
  Pose3 init = cand.init;
  if (c.correlative && !cand.place) {
    const std::optional<Pose3> start = uniqueStart(graph, cand);
    if (!start) {
      ++stats_.ambiguous;
      return std::nullopt;
    }
    init = *start;
  }
  const Cloud target = submap(graph, old_kf, false);
  const IcpTarget icp_target(voxelFilter(target, c.voxel_m));
  const Cloud source = voxelFilter(graph.clouds().get(cur.cloud), c.voxel_m);
  const LoopVerifyOptions vo = loopVerifyOptions(c);
  IcpResult icp;
  if (cand.place) {  // ICP from the descriptor's yaw; it may not turn far from it
    const Keyframe& old = graph.at(static_cast<std::size_t>(old_kf));
    const LoopVerification v = verifyLoop(icp_target, old.T_world, source, *cand.place, vo);
    if (!v.accepted) return std::nullopt;
    icp = v.icp;
  } else {
    icp = icp_target.align(source, init, c.icp_iterations, c.icp_max_corr_m);
  }
  logDebug("loop candidate kf " + std::to_string(old_kf) + " -> " + std::to_string(n - 1) +
           ": fitness " + std::to_string(icp.fitness_m2) + " inliers " +
           std::to_string(icp.inlier_ratio) + (cand.place ? " (place descriptor)" : ""));
  if (!vo.accept(icp)) return std::nullopt;
  const std::optional<IcpResult> pinned = pinDown(graph, old_kf, icp_target, source, icp);
  if (!pinned) {
    ++stats_.ambiguous;
    return std::nullopt;
  }
  icp = *pinned;
  const double correction = (icp.T_target_source.translation() - cur.T_world.translation()).norm();
  const bool outside_gate = cand.place && correction > cand.gate_m;
  if (outside_gate || !plausibleLoopCorrection(correction, graph.drivenSinceLoop(), cfg_)) {
    ++stats_.rejected;
    logDebug("loop candidate rejected: correction " + std::to_string(correction) + " m after " +
             std::to_string(graph.drivenSinceLoop()) + " m");
    return std::nullopt;
  }
  if (!consistentWithLastClosure(graph, old_kf, icp)) {
    ++stats_.rejected;
    return std::nullopt;
  }
  return icp;
}

bool LoopCloser::consistentWithLastClosure(const KeyframeGraph& graph, int old_kf,
                                           const IcpResult& icp) const {
  if (stats_.loops.empty()) return true;
  const ClosureCycle cycle = closureCycle(graph, stats_.loops.back(), old_kf, icp.T_target_source);
  if (consistentCycle(cycle, cfg_.loop)) return true;
  const Keyframe& old = graph.at(static_cast<std::size_t>(old_kf));
  const Vec3 rel = (old.T_world.inverse() * icp.T_target_source).translation();
  logDebug("loop candidate rejected: the cycle with the closure before misses by " +
           std::to_string(cycle.error_m) + " m over " + std::to_string(cycle.chain_m) +
           " m of chains (t " + std::to_string(old.t) + " -> " + std::to_string(graph.back().t) +
           " s, relative position " + std::to_string(rel.x()) + " " + std::to_string(rel.y()) +
           " " + std::to_string(rel.z()) + " m)");
  return false;
}

std::optional<IcpResult> LoopCloser::pinDown(const KeyframeGraph& graph, int old_kf,
                                             const IcpTarget& target, const Cloud& source,
                                             const IcpResult& icp) const {
  const LoopConfig& c = cfg_.loop;
  const std::optional<IcpResult> unique = uniqueMatch(target, source, icp, loopAmbiguity(c));
  if (!unique) {
    logDebug("loop candidate refused: a rival fits as well");
    return std::nullopt;
  }
  const bool rival_taken = !unique->T_target_source.isApprox(icp.T_target_source);
  if (rival_taken)
    logDebug(
        "loop candidate: the better-fitting rival taken, " +
        std::to_string(
            (unique->T_target_source.translation() - icp.T_target_source.translation()).norm()) +
        " m away");
  const double conditioning = horizontalConditioning(
      target.translationInformation(source, unique->T_target_source, c.icp_max_corr_m / 3));
  if (conditioning < c.min_horizontal_conditioning) {
    logDebug("loop candidate refused: horizontal conditioning " + std::to_string(conditioning));
    return std::nullopt;
  }
  if (c.submap_agreement_m < 0) return unique;
  const int each_side = c.submap_keyframes;
  const std::vector<Cloud> sides{
      voxelFilter(keyframeClouds(graph, old_kf - each_side, old_kf - 1, false), c.voxel_m),
      voxelFilter(keyframeClouds(graph, old_kf + 1, old_kf + each_side, false), c.voxel_m)};
  const SubmapAgreement agreement = submapAgreement(sides, source, *unique, loopSubmapAgreement(c));
  logDebug("loop candidate: horizontal conditioning " + std::to_string(conditioning) +
           ", the submap's sides put it " + std::to_string(agreement.apart_m) + " m apart (" +
           std::to_string(agreement.sides_matched) + " matched)");
  if (!submapBacks(agreement, c.submap_agreement_m, rival_taken)) return std::nullopt;
  return unique;
}

void LoopCloser::accept(KeyframeGraph& graph, const LoopCandidate& c, const IcpResult& icp,
                        StageTimes& times) {
  const int old_kf = c.keyframe;
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
  const double up = icp.T_target_source.translation().z() - cur.T_world.translation().z();
  stats_.loops.push_back({old_kf, n - 1, old.t, cur.t, icp.fitness_m2, correction, up, e.T_from_to,
                          c.place.has_value()});
  last_loop_t_ = cur.t;
  const double t_cur = cur.t;
  const double t0 = cpuNow();
  graph.closeLoop(e);
  times.pose_graph += cpuSince(t0);
  logInfo("loop closure: keyframe " + std::to_string(n - 1) + " (t=" + std::to_string(t_cur) +
          " s) matches keyframe " + std::to_string(old_kf) + ", fitness " +
          std::to_string(icp.fitness_m2) + " m^2");
}

}  // namespace slamroute::evaluate::slam
