// Inter-vehicle closures: a place-descriptor candidate among the other vehicle's keyframes near
// the query's estimate, verified as the SLAM verifies its own loops (ICP from the descriptor's
// yaw, fitness and inlier share, yaw change, no restart elsewhere fitting as well).
#include <Eigen/Eigenvalues>
#include <algorithm>

#include "FleetInternal.hpp"
#include "slamroute/evaluate/LoopVerification.hpp"
#include "slamroute/evaluate/PlaceDatabase.hpp"
#include "slamroute/evaluate/PlaceDescriptor.hpp"

namespace slamroute::evaluate {
namespace {

/// A vehicle's keyframe clouds (body frame) and their place descriptors.
struct VehicleClouds {
  std::vector<Cloud> body;
  std::vector<PlaceDescriptor> descriptors;
};

VehicleClouds vehicleClouds(const FleetVehicleInput& v, const std::vector<FleetKeyframe>& kfs,
                            const Config& cfg) {
  VehicleClouds c;
  const double height = v.scans->spec().mount_height_m;
  for (const auto& kf : kfs) {
    c.body.push_back(bodyCloud(*v.scans, v.estimate, kf.scan, cfg.loop.voxel_m));
    c.descriptors.push_back(makePlaceDescriptor(c.body.back(), height, cfg.loop.place));
  }
  return c;
}

/// Keyframe k's cloud with its neighbours (each side `each_side`), in k's body frame.
Cloud submap(const VehicleClouds& c, const std::vector<FleetKeyframe>& kfs, int k, int each_side,
             double voxel_m) {
  Cloud out;
  const Pose3 T_k_world = kfs[static_cast<std::size_t>(k)].pose.inverse();
  const int n = static_cast<int>(kfs.size());
  for (int j = std::max(0, k - each_side); j <= std::min(n - 1, k + each_side); ++j) {
    const Cloud part = transformed(c.body[static_cast<std::size_t>(j)],
                                   T_k_world * kfs[static_cast<std::size_t>(j)].pose);
    out.insert(out.end(), part.begin(), part.end());
  }
  return voxelFilter(out, voxel_m);
}

/// Closures of vehicle b's keyframes against vehicle a's.
void closePair(int a, int b, const std::vector<std::vector<FleetKeyframe>>& kfs,
               const std::vector<VehicleClouds>& clouds, const Config& cfg,
               const FleetMergeOptions& opt, std::vector<FleetClosure>& out, int& candidates) {
  const auto& ka = kfs[static_cast<std::size_t>(a)];
  const auto& kb = kfs[static_cast<std::size_t>(b)];
  const auto& ca = clouds[static_cast<std::size_t>(a)];
  const auto& cb = clouds[static_cast<std::size_t>(b)];
  PlaceDatabase db(cfg.loop.place);
  for (std::size_t k = 0; k < ka.size(); ++k)
    db.add(static_cast<int>(k), ca.descriptors[k], ka[k].pose.translation());
  const LoopVerifyOptions vo = loopVerifyOptions(cfg.loop);
  const IcpAmbiguity amb = loopAmbiguity(cfg.loop);
  for (std::size_t k = 0; k < kb.size(); ++k) {
    PlaceQuery q;
    q.gate_centre = kb[k].pose.translation();
    q.gate_radius_m = opt.gate_m;
    const auto found = db.query(cb.descriptors[k], q);
    const auto same_level = std::find_if(found.begin(), found.end(), [&](const PlaceCandidate& p) {
      return onSameLevel(ka[static_cast<std::size_t>(p.keyframe)].pose.translation(),
                         kb[k].pose.translation(), cfg.loop);
    });
    if (same_level == found.end()) continue;
    const PlaceCandidate& c = *same_level;
    ++candidates;
    const IcpTarget target(
        submap(ca, ka, c.keyframe, opt.target_keyframes_each_side, cfg.loop.voxel_m));
    const LoopVerification v = verifyLoop(target, Pose3::Identity(), cb.body[k], c, vo);
    if (!v.accepted) continue;
    if (ambiguousMatch(strongestRival(target, cb.body[k], v.icp, amb), amb)) continue;
    const double conditioning = horizontalConditioning(
        target.translationInformation(cb.body[k], v.icp.T_target_source, vo.icp_max_corr_m / 3));
    if (conditioning < opt.min_horizontal_conditioning) continue;
    const auto& kfa = ka[static_cast<std::size_t>(c.keyframe)];
    out.push_back({a, b, c.keyframe, static_cast<int>(k), kfa.t, kb[k].t, v.icp.T_target_source,
                   v.icp.fitness_m2, conditioning});
  }
}

}  // namespace

std::vector<FleetClosure> findFleetClosures(const std::vector<FleetVehicleInput>& vehicles,
                                            const std::vector<std::vector<FleetKeyframe>>& kfs,
                                            const Config& cfg, const FleetMergeOptions& opt,
                                            int* candidates) {
  std::vector<VehicleClouds> clouds;
  for (std::size_t v = 0; v < vehicles.size(); ++v)
    clouds.push_back(vehicleClouds(vehicles[v], kfs[v], cfg));
  std::vector<FleetClosure> out;
  int tried = 0;
  const int n = static_cast<int>(vehicles.size());
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n; ++b) closePair(a, b, kfs, clouds, cfg, opt, out, tried);
  if (candidates) *candidates = tried;
  return out;
}

}  // namespace slamroute::evaluate
