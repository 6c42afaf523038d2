// Each side of a loop closure's submap matched on its own (SubmapAgreement.hpp).
#include "slamroute/evaluate/SubmapAgreement.hpp"

#include <algorithm>

namespace slamroute::evaluate {

SubmapAgreement submapAgreement(const std::vector<Cloud>& sides, const Cloud& query_body,
                                const IcpResult& whole, const SubmapAgreementOptions& opt) {
  SubmapAgreement a;
  for (const Cloud& side : sides) {
    if (side.empty()) continue;
    // Started at the whole's result, a side that leaves a direction open (a straight street)
    // stays there along it: only what the side itself measures moves the match.
    const IcpResult r = IcpTarget(side).align(query_body, whole.T_target_source, opt.icp_iterations,
                                              opt.icp_max_corr_m);
    if (!opt.accept(r)) continue;
    ++a.sides_matched;
    a.apart_m = std::max(
        a.apart_m, (r.T_target_source.translation() - whole.T_target_source.translation()).norm());
  }
  return a;
}

bool submapBacks(const SubmapAgreement& a, double agreement_m, bool rival_taken) {
  if (a.apart_m > agreement_m) return false;
  return !rival_taken || a.sides_matched > 0;
}

}  // namespace slamroute::evaluate
