// ICP check of a place-recognition candidate from the descriptor's yaw (LoopVerification.hpp).
#include "slamroute/evaluate/LoopVerification.hpp"

#include <cmath>
#include <numbers>

#include "slamroute/core/Yaw.hpp"

namespace slamroute::evaluate {

LoopVerifyOptions loopVerifyOptions(const LoopConfig& c) {
  LoopVerifyOptions o;
  o.icp_iterations = c.icp_iterations;
  o.icp_max_corr_m = c.icp_max_corr_m;
  o.accept = IcpAcceptance{c.fitness_m2, c.min_inlier_ratio};
  o.max_yaw_change_deg = c.place_max_yaw_change_deg;
  return o;
}

IcpAmbiguity loopAmbiguity(const LoopConfig& c) {
  IcpAmbiguity a;
  a.along_m = c.ambiguity_along_m;
  a.across_m = c.ambiguity_across_m;
  a.separation_m = c.ambiguity_separation_m;
  a.inlier_margin = c.ambiguity_inlier_margin;
  a.rival_share = c.ambiguity_rival_share;
  a.iterations = c.icp_iterations;
  a.max_corr_m = c.icp_max_corr_m;
  a.accept = IcpAcceptance{c.fitness_m2, c.min_inlier_ratio};
  return a;
}

bool onSameLevel(const Vec3& a, const Vec3& b, const LoopConfig& c) {
  return std::abs(a.z() - b.z()) <= c.max_height_gap_m;
}

SubmapAgreementOptions loopSubmapAgreement(const LoopConfig& c) {
  SubmapAgreementOptions o;
  o.icp_iterations = c.icp_iterations;
  o.icp_max_corr_m = c.icp_max_corr_m;
  o.accept = IcpAcceptance{c.fitness_m2, c.min_inlier_ratio};
  return o;
}

namespace {

/// |a - b| wrapped into [0, pi].
double angleBetween(double a, double b) {
  return std::abs(std::remainder(a - b, 2.0 * std::numbers::pi));
}

}  // namespace

LoopVerification verifyLoop(const IcpTarget& target, const Pose3& T_F_candidate,
                            const Cloud& query_body, const PlaceCandidate& c,
                            const LoopVerifyOptions& opt) {
  Pose3 turn = Pose3::Identity();
  turn.linear() = Eigen::AngleAxisd(c.yaw_rad, Vec3::UnitZ()).toRotationMatrix();
  LoopVerification v;
  v.icp = target.align(query_body, T_F_candidate * turn, opt.icp_iterations, opt.icp_max_corr_m);
  const Pose3 T_candidate_query = T_F_candidate.inverse() * v.icp.T_target_source;
  v.yaw_change_deg = angleBetween(yawOf(T_candidate_query), c.yaw_rad) * 180.0 / std::numbers::pi;
  v.accepted = opt.accept(v.icp) && v.yaw_change_deg <= opt.max_yaw_change_deg;
  return v;
}

}  // namespace slamroute::evaluate
