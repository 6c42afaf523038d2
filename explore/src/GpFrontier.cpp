// GpFrontierMap: local-kernel GP occupancy and the frontier probability (eqs. 6-11).
#include "slamroute/explore/GpFrontier.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace slamroute::explore {

GpFrontierMap::GpFrontierMap(const OccupancyGrid& grid, const GpConfig& cfg)
    : grid_(grid), cfg_(cfg) {
  const int n = cfg.kernel_cells;
  if (n < 1 || n % 2 == 0) throw std::invalid_argument("gp: kernel_cells must be odd and >= 1");
  half_ = n / 2;
  k_.resize(static_cast<std::size_t>(n) * static_cast<std::size_t>(n));
  for (int p = 0; p < n; ++p)
    for (int q = 0; q < n; ++q) {
      const double r = std::hypot(p - (n - 1) / 2.0, q - (n - 1) / 2.0);
      const double a = std::sqrt(3.0) * r / cfg.length_scale_cells;
      k_[static_cast<std::size_t>(p * n + q)] = cfg.signal_var * (1.0 + a) * std::exp(-a);
    }
  for (double v : k_) k_sum_ += v;
  var_min_ = cfg.signal_var * cfg.noise_var / (k_sum_ + cfg.noise_var);
}

double GpFrontierMap::logistic(double mu, double var) const {
  const double omega = var_min_ / var * mu;
  return 1.0 / (1.0 + std::exp(-cfg_.gamma * omega));
}

GpCell GpFrontierMap::at(int col, int row) const {
  const int n = 2 * half_ + 1;
  double sum_emp = 0.0, sum_obs_k = 0.0;
  for (int p = 0; p < n; ++p)
    for (int q = 0; q < n; ++q) {
      const double k = k_[static_cast<std::size_t>(p * n + q)];
      const Cell c = grid_.atColRow(col + q - half_, row + p - half_);
      const double v = c == Cell::Ground ? cfg_.p_emp : cfg_.p_non_emp;
      sum_emp += k * (2.0 * v - 1.0);
      if (c == Cell::Obstacle) sum_obs_k += k;
    }
  const double sn2 = cfg_.noise_var, sf2 = cfg_.signal_var;
  GpCell g;
  g.var_emp = sf2 * sn2 / (k_sum_ + sn2);
  g.p_emp = logistic(sum_emp / (k_sum_ + sn2), g.var_emp);
  g.var_obs = sf2 * sn2 / (sum_obs_k + sn2);
  g.p_obs = logistic(sum_obs_k / (sum_obs_k + sn2), g.var_obs);
  const double var_gp = 1.0 / (1.0 / g.var_emp + 1.0 / g.var_obs);
  const double mu_gp = var_gp * (g.p_emp / g.var_emp + g.p_obs / g.var_obs);
  g.p_gp = logistic(2.0 * mu_gp - 1.0, var_min_);
  return g;
}

double GpFrontierMap::frontierProbability(int idx) const {
  const int c = grid_.col(idx), r = grid_.row(idx);
  const GpCell xm = at(c - 1, r), xp = at(c + 1, r), ym = at(c, r - 1), yp = at(c, r + 1);
  const GpCell here = at(c, r);
  const double grad_gp = (std::abs(xp.p_gp - xm.p_gp) + std::abs(yp.p_gp - ym.p_gp)) / 2.0;
  const double grad_obs = (std::abs(xp.p_obs - xm.p_obs) + std::abs(yp.p_obs - ym.p_obs)) / 2.0;
  const double p = grad_gp - cfg_.beta * (grad_obs + here.p_obs - cfg_.p_non_emp);
  return std::max(0.0, p);
}

}  // namespace slamroute::explore
