#pragma once
// Whether a loop closure's submap is one rigid map. The closure's relative pose is read against
// the candidate keyframe's pose, but ICP matched the new keyframe against the whole submap of
// keyframes around the candidate. When the front end's poses within that submap disagree (a
// U-turn dead-reckoned on the wheels while no scan registered shifts every keyframe after it),
// ICP follows one part, or settles between them, with a good fit, and the relative pose to the
// candidate carries the shift. Matched on its own from the whole submap's result, each side of
// the submap (the keyframes before the candidate, and those after it) ends where the whole did
// when the submap is rigid, and apart from it when it is not.
#include <vector>

#include "slamroute/evaluate/Registration.hpp"

namespace slamroute::evaluate {

struct SubmapAgreementOptions {
  int icp_iterations = 30;
  double icp_max_corr_m = 2.0;  ///< ICP correspondence distance (shrinks to a third) [m]
  IcpAcceptance accept;         ///< a side's match counts only when it passes this
};

struct SubmapAgreement {
  double apart_m = 0.0;   ///< farthest a side's counted match ended from the whole's [m]
  int sides_matched = 0;  ///< sides whose match passed the acceptance
};

/// `sides`: the parts of the submap in its frame (empty ones are skipped); `query_body`: the new
/// keyframe's cloud in its body frame; `whole`: its ICP match against the whole submap.
SubmapAgreement submapAgreement(const std::vector<Cloud>& sides, const Cloud& query_body,
                                const IcpResult& whole, const SubmapAgreementOptions& opt);

/// The submap backs a loop-closure match: the sides that matched alone end within agreement_m of
/// it, and a match that is a better-fitting rival taken in place of ICP's first (a jump of metres
/// along the street) has at least one such side. With no side matched the check is empty, which
/// is enough for a match where ICP ended from the estimate, not for a jump to a look-alike.
bool submapBacks(const SubmapAgreement& a, double agreement_m, bool rival_taken);

}  // namespace slamroute::evaluate
