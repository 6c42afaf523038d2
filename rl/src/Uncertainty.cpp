// C_k along a route (see Uncertainty.hpp).
#include "slamroute/rl/Uncertainty.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>

#include "Index.hpp"

namespace slamroute::rl {

double positionDOptimality(const Eigen::Matrix3d& cov) {
  return std::sqrt(std::max(cov.topLeftCorner<2, 2>().determinant(), 0.0));
}

EdgeMotions edgeMotions(const PlanGraph& pg, const EifConfig& cfg) {
  auto v = std::make_shared<std::vector<EdgeMotion>>();
  v->reserve(sz(pg.m));
  for (int e = 0; e < pg.m; ++e)
    v->push_back(edgeMotion(cfg, pg.len[sz(e)], pg.heading[sz(e)], pg.weight[sz(e)]));
  return v;
}

UncertaintyTracker::UncertaintyTracker(const PlanGraph& pg, const EifConfig& cfg, int start,
                                       EdgeMotions motions)
    : pg_(&pg), cfg_(&cfg), motions_(std::move(motions)) {
  if (!motions_) motions_ = edgeMotions(pg, cfg);
  cov_ = PoseEif(cfg).info().inverse();
  r_lc_ = closureNoise(cfg);
  node_cov_.resize(sz(pg.n));
  place_c_.assign(sz(pg.n), std::numeric_limits<double>::infinity());
  last_visit_m_.assign(sz(pg.n), 0.0);
  mapped_.assign(sz(pg.n), 0);
  c_ = positionDOptimality(cov_);
  mapped_[sz(start)] = 1;
  node_cov_[sz(start)] = cov_;
  place_c_[sz(start)] = c_;
}

double UncertaintyTracker::drive(int e) {
  const EdgeMotion& mo = (*motions_)[sz(e)];
  cov_ = mo.F * cov_ * mo.F.transpose() + mo.Q;
  travelled_m_ += pg_->len[sz(e)];
  const std::size_t w = sz(pg_->v[sz(e)]);
  if (mapped_[w] && travelled_m_ - last_visit_m_[w] >= cfg_->loop_min_travel_m) {
    const Eigen::Matrix3d anchored = node_cov_[w] + r_lc_;
    if (anchored.determinant() < cov_.determinant()) cov_ = anchored;
    ++closures_;
  }
  c_ = positionDOptimality(cov_);
  if (!mapped_[w] || c_ < place_c_[w]) {
    node_cov_[w] = cov_;
    place_c_[w] = c_;
  }
  mapped_[w] = 1;
  last_visit_m_[w] = travelled_m_;
  return c_;
}

UncertaintySeries predictUncertainty(const PlanGraph& pg, const EifConfig& cfg, int start,
                                     const std::vector<int>& edges) {
  UncertaintyTracker t(pg, cfg, start, nullptr);
  UncertaintySeries s;
  s.c_m2.reserve(edges.size());
  for (int e : edges) {
    s.c_m2.push_back(t.drive(e));
    s.max_m2 = std::max(s.max_m2, s.c_m2.back());
    s.mean_m2 += s.c_m2.back();
  }
  if (!edges.empty()) s.mean_m2 /= static_cast<double>(edges.size());
  s.closures = t.closures();
  return s;
}

}  // namespace slamroute::rl
