// ICP check of a place-recognition candidate from the descriptor's yaw (LoopVerification.hpp).
#include "slamroute/evaluate/LoopVerification.hpp"

#include <cmath>
#include <numbers>

#include "slamroute/core/Yaw.hpp"

namespace slamroute::evaluate {
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
