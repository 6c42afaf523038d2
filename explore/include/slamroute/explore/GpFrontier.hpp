#pragma once
// GP occupancy map with the local-kernel approximation and the frontier probability of the GP
// frontier seed paper (Choi et al., KIEE 2024), on the shared occupancy grid.
//
// Local kernel (eq. 10): an n x n Matern-3/2 kernel k(p, q) over cell offsets. Both GPs are
// evaluated per cell from the training cells inside that window, each window pooled into one
// observation (a GP whose posterior mean and variance given the window are
//   mu = sum k_j y_j / (sum k_j + sigma_n^2),  sigma^2 = sigma_f^2 sigma_n^2 / (sum k_j +
//   sigma_n^2);
// no matrix inverse, which is the point of the paper's convolution):
//  - the unoccupied GP trains on every cell: p_emp for ground, p_non_emp otherwise (Alg. 2),
//    mapped to y = 2p - 1;
//  - the occupied GP trains on the obstacle cells with y = 1 (the paper solves eqs. 3-4 on the
//    returns; the same pooling keeps it local and cheap here).
// Each mean goes through the logistic eqs. 6-7 (omega = sigma_min^2 / sigma^2 * mu, sigma_min^2
// the variance of a fully observed window); the two are fused with the BCM (eqs. 8-9) and the
// fused mean, centred to 2 mu - 1, through the logistic again gives p_GP.
// Frontier probability (eq. 11), gradients by central differences per cell:
//   p_frontier = |grad p_GP|_1 - beta (|grad p_obs|_1 + p_obs - p_unknown), floored at 0.
#include <vector>

#include "slamroute/explore/Config.hpp"
#include "slamroute/explore/OccupancyGrid.hpp"

namespace slamroute::explore {

struct GpCell {
  double p_emp = 0.5, var_emp = 0.0;  ///< unoccupied GP after the logistic, its variance
  double p_obs = 0.5, var_obs = 0.0;  ///< occupied GP after the logistic, its variance
  double p_gp = 0.5;                  ///< fused occupancy probability
};

class GpFrontierMap {
 public:
  /// Throws std::invalid_argument on an even or non-positive kernel size.
  GpFrontierMap(const OccupancyGrid& grid, const GpConfig& cfg);
  /// The GP quantities of cell (col, row); cells outside the grid are unknown.
  GpCell at(int col, int row) const;
  /// Eq. 11 at a cell index.
  double frontierProbability(int idx) const;
  /// The local kernel, row-major n x n.
  const std::vector<double>& kernel() const { return k_; }

 private:
  double logistic(double mu, double var) const;
  const OccupancyGrid& grid_;
  GpConfig cfg_;
  int half_ = 0;
  std::vector<double> k_;
  double k_sum_ = 0.0, var_min_ = 0.0;
};

}  // namespace slamroute::explore
