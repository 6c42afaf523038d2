// Keyframe pose-graph optimisation with Ceres (relative-pose residuals, quaternion manifold).
#include "slamroute/evaluate/PoseGraph.hpp"

#include <ceres/ceres.h>

#include <stdexcept>

namespace slamroute::evaluate {
namespace {

struct RelativePoseError {
  RelativePoseError(const Pose3& T_ab, double sigma_m, double sigma_rad)
      : p_ab(T_ab.translation()), q_ab(T_ab.rotation()), wt(1.0 / sigma_m), wr(1.0 / sigma_rad) {}

  template <class T>
  bool operator()(const T* pa, const T* qa, const T* pb, const T* qb, T* res) const {
    using V3 = Eigen::Matrix<T, 3, 1>;
    using Q = Eigen::Quaternion<T>;
    Eigen::Map<const V3> p_a(pa), p_b(pb);
    Eigen::Map<const Q> q_a(qa), q_b(qb);
    const Q q_a_inv = q_a.conjugate();
    const Q q_ab_est = q_a_inv * q_b;
    const V3 p_ab_est = q_a_inv * (p_b - p_a);
    const Q dq = q_ab.template cast<T>() * q_ab_est.conjugate();
    Eigen::Map<Eigen::Matrix<T, 6, 1>> r(res);
    r.template head<3>() = T(wt) * (p_ab_est - p_ab.template cast<T>());
    r.template tail<3>() = T(2.0 * wr) * dq.vec();
    return true;
  }
  Vec3 p_ab;
  Eigen::Quaterniond q_ab;
  double wt, wr;
};

}  // namespace

PoseGraphResult optimizePoseGraph(std::vector<Pose3>& poses,
                                  const std::vector<PoseGraphEdge>& edges, int fixed) {
  PoseGraphResult out;
  if (poses.empty()) return out;
  const int n = static_cast<int>(poses.size());
  std::vector<std::array<double, 3>> p(poses.size());
  std::vector<std::array<double, 4>> q(poses.size());
  for (std::size_t i = 0; i < poses.size(); ++i) {
    const Eigen::Quaterniond qq(poses[i].rotation());
    p[i] = {poses[i].translation().x(), poses[i].translation().y(), poses[i].translation().z()};
    q[i] = {qq.x(), qq.y(), qq.z(), qq.w()};
  }
  ceres::Problem problem;
  for (const auto& e : edges) {
    if (e.from < 0 || e.to < 0 || e.from >= n || e.to >= n)
      throw std::invalid_argument("optimizePoseGraph: edge refers to a missing node");
    auto* cost = new ceres::AutoDiffCostFunction<RelativePoseError, 6, 3, 4, 3, 4>(
        new RelativePoseError(e.T_from_to, e.sigma_m, e.sigma_rad));
    const auto a = static_cast<std::size_t>(e.from), b = static_cast<std::size_t>(e.to);
    ceres::LossFunction* loss =
        e.cauchy_sigmas > 0.0 ? new ceres::CauchyLoss(e.cauchy_sigmas) : nullptr;
    problem.AddResidualBlock(cost, loss, p[a].data(), q[a].data(), p[b].data(), q[b].data());
  }
  for (std::size_t i = 0; i < poses.size(); ++i) {
    if (!problem.HasParameterBlock(q[i].data())) continue;
    problem.SetManifold(q[i].data(), new ceres::EigenQuaternionManifold);
  }
  const auto f = static_cast<std::size_t>(fixed);
  if (problem.HasParameterBlock(p[f].data())) {
    problem.SetParameterBlockConstant(p[f].data());
    problem.SetParameterBlockConstant(q[f].data());
  }
  ceres::Solver::Options opt;
  opt.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  opt.max_num_iterations = 50;
  opt.num_threads = 1;
  ceres::Solver::Summary summary;
  ceres::Solve(opt, &problem, &summary);
  out.initial_cost = summary.initial_cost;
  out.final_cost = summary.final_cost;
  out.iterations = static_cast<int>(summary.iterations.size());
  out.converged = summary.termination_type == ceres::CONVERGENCE;
  for (std::size_t i = 0; i < poses.size(); ++i) {
    Pose3 T = Pose3::Identity();
    T.linear() =
        Eigen::Quaterniond(q[i][3], q[i][0], q[i][1], q[i][2]).normalized().toRotationMatrix();
    T.translation() = Vec3(p[i][0], p[i][1], p[i][2]);
    poses[i] = T;
  }
  return out;
}

}  // namespace slamroute::evaluate
