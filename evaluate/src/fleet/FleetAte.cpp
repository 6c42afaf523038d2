// ATE of a fleet under one common alignment: a merged map is one frame, so its vehicles are
// judged together, not each under the alignment that suits it best.
#include <cmath>

#include "FleetInternal.hpp"
#include "slamroute/evaluate/Metrics.hpp"

namespace slamroute::evaluate {

std::vector<double> commonAteRmse(const std::vector<Trajectory>& estimates,
                                  const std::vector<Trajectory>& ground_truths, double max_dt_s,
                                  Pose3* T_gt_est) {
  std::vector<std::vector<PosePair>> pairs;
  std::vector<PosePair> all;
  for (std::size_t v = 0; v < estimates.size(); ++v) {
    pairs.push_back(associate(estimates[v], ground_truths[v], max_dt_s));
    all.insert(all.end(), pairs.back().begin(), pairs.back().end());
  }
  const Pose3 T = alignUmeyama(all);
  if (T_gt_est) *T_gt_est = T;
  std::vector<double> rmse;
  double sum_all = 0.0;
  for (const auto& ps : pairs) {
    double sum = 0.0;
    for (const auto& p : ps) sum += (T * p.est.translation() - p.gt.translation()).squaredNorm();
    sum_all += sum;
    rmse.push_back(ps.empty() ? 0.0 : std::sqrt(sum / static_cast<double>(ps.size())));
  }
  rmse.push_back(all.empty() ? 0.0 : std::sqrt(sum_all / static_cast<double>(all.size())));
  return rmse;
}

}  // namespace slamroute::evaluate
