#pragma once
// Geometric verification of a place-recognition candidate: point-to-plane ICP of the query
// keyframe's cloud against the candidate's target cloud, started at the candidate's pose turned
// by the descriptor's yaw. The descriptor knows the rotation, which ICP with correspondences of a
// few metres cannot find by itself; the translation it leaves to ICP (a place match means "within
// a few metres").
#include "slamroute/evaluate/Config.hpp"
#include "slamroute/evaluate/PlaceDatabase.hpp"
#include "slamroute/evaluate/Registration.hpp"
#include "slamroute/evaluate/SubmapAgreement.hpp"

namespace slamroute::evaluate {

struct LoopVerifyOptions {
  int icp_iterations = 30;
  double icp_max_corr_m = 2.0;  ///< ICP correspondence distance (shrinks to a third) [m]
  IcpAcceptance accept;         ///< fitness and inlier share the ICP result must reach
  /// ICP may turn the descriptor's yaw by at most this; more means it slid into another
  /// minimum, not the one the descriptor pointed at (two 6-degree sectors by default) [deg]
  double max_yaw_change_deg = 12.0;
};

struct LoopVerification {
  IcpResult icp;                ///< T_target_source: the query keyframe in the target's frame
  double yaw_change_deg = 0.0;  ///< |ICP yaw - descriptor yaw| relative to the candidate [deg]
  bool accepted = false;        ///< passes opt.accept and opt.max_yaw_change_deg
};

/// The loop closure's ICP checks as configured (LoopConfig): verification of a descriptor's
/// candidate, where to look for a better match elsewhere, and the submap's sides matched alone.
LoopVerifyOptions loopVerifyOptions(const LoopConfig& c);
IcpAmbiguity loopAmbiguity(const LoopConfig& c);
SubmapAgreementOptions loopSubmapAgreement(const LoopConfig& c);
/// Two keyframe positions within loop.max_height_gap_m of each other's height: not one on a
/// bridge deck and the other on the street under it (the only pairs a loop may join).
bool onSameLevel(const Vec3& a, const Vec3& b, const LoopConfig& c);

/// `target`: the candidate's cloud (or submap) in frame F; `T_F_candidate`: the candidate
/// keyframe's pose in F; `query_body`: the query keyframe's cloud in its body frame; `c`: the
/// database's match (its yaw is the query's yaw in the candidate's body frame).
LoopVerification verifyLoop(const IcpTarget& target, const Pose3& T_F_candidate,
                            const Cloud& query_body, const PlaceCandidate& c,
                            const LoopVerifyOptions& opt);

}  // namespace slamroute::evaluate
