// Keyframe pose-graph optimisation with Ceres (relative-pose residuals, quaternion manifold).
#include "slamroute/evaluate/PoseGraph.hpp"

#include <ceres/ceres.h>

#include <array>
#include <cmath>
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

/// pitch(q) - (imu - b), in sigmas; with R = Rz(yaw) Ry(pitch) Rx(roll), R(2,0) = -sin(pitch).
struct PitchError {
  PitchError(double imu_pitch_rad, double sigma_rad) : imu(imu_pitch_rad), w(1.0 / sigma_rad) {}

  template <class T>
  bool operator()(const T* q, const T* b, T* res) const {
    const T r20 = T(2.0) * (q[0] * q[2] - q[3] * q[1]);  // q = (x, y, z, w)
    const T pitch = asin(-r20);
    res[0] = T(w) * (pitch - (T(imu) - b[0]));
    return true;
  }
  double imu, w;
};

struct BiasPrior {
  BiasPrior(double prior_rad, double sigma_rad) : prior(prior_rad), w(1.0 / sigma_rad) {}
  template <class T>
  bool operator()(const T* b, T* res) const {
    res[0] = T(w) * (b[0] - T(prior));
    return true;
  }
  double prior, w;
};

/// The graph's unknowns in Ceres' layout: positions, quaternions (x, y, z, w), the pitch bias.
struct Unknowns {
  explicit Unknowns(const std::vector<Pose3>& poses) : p(poses.size()), q(poses.size()) {
    for (std::size_t i = 0; i < poses.size(); ++i) {
      const Eigen::Quaterniond qq(poses[i].rotation());
      const Vec3 t = poses[i].translation();
      p[i] = {t.x(), t.y(), t.z()};
      q[i] = {qq.x(), qq.y(), qq.z(), qq.w()};
    }
  }
  Pose3 pose(std::size_t i) const {
    Pose3 T = Pose3::Identity();
    T.linear() =
        Eigen::Quaterniond(q[i][3], q[i][0], q[i][1], q[i][2]).normalized().toRotationMatrix();
    T.translation() = Vec3(p[i][0], p[i][1], p[i][2]);
    return T;
  }
  std::vector<std::array<double, 3>> p;
  std::vector<std::array<double, 4>> q;
  double bias = 0.0;
};

void addEdges(ceres::Problem& problem, Unknowns& x, const std::vector<PoseGraphEdge>& edges) {
  const auto n = static_cast<int>(x.p.size());
  for (const auto& e : edges) {
    if (e.from < 0 || e.to < 0 || e.from >= n || e.to >= n)
      throw std::invalid_argument("optimizePoseGraph: edge refers to a missing node");
    auto* cost = new ceres::AutoDiffCostFunction<RelativePoseError, 6, 3, 4, 3, 4>(
        new RelativePoseError(e.T_from_to, e.sigma_m, e.sigma_rad));
    const auto a = static_cast<std::size_t>(e.from), b = static_cast<std::size_t>(e.to);
    ceres::LossFunction* loss =
        e.cauchy_sigmas > 0.0 ? new ceres::CauchyLoss(e.cauchy_sigmas) : nullptr;
    problem.AddResidualBlock(cost, loss, x.p[a].data(), x.q[a].data(), x.p[b].data(),
                             x.q[b].data());
  }
}

void addPitchFactors(ceres::Problem& problem, Unknowns& x, const PitchFactors& f) {
  x.bias = f.bias_prior_rad;
  if (!(f.sigma_rad > 0)) return;
  if (f.imu_pitch_rad.size() != x.q.size())
    throw std::invalid_argument("optimizePoseGraph: one IMU pitch per node expected");
  for (std::size_t i = 0; i < x.q.size(); ++i) {
    if (!std::isfinite(f.imu_pitch_rad[i]) || !problem.HasParameterBlock(x.q[i].data())) continue;
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<PitchError, 1, 4, 1>(
                                 new PitchError(f.imu_pitch_rad[i], f.sigma_rad)),
                             nullptr, x.q[i].data(), &x.bias);
  }
  if (!problem.HasParameterBlock(&x.bias)) return;
  if (f.bias_sigma_rad > 0)
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<BiasPrior, 1, 1>(
                                 new BiasPrior(f.bias_prior_rad, f.bias_sigma_rad)),
                             nullptr, &x.bias);
  else
    problem.SetParameterBlockConstant(&x.bias);
}

}  // namespace

PoseGraphResult optimizePoseGraph(std::vector<Pose3>& poses,
                                  const std::vector<PoseGraphEdge>& edges, int fixed,
                                  const PitchFactors& pitch) {
  PoseGraphResult out;
  if (poses.empty()) return out;
  Unknowns x(poses);
  ceres::Problem problem;
  addEdges(problem, x, edges);
  addPitchFactors(problem, x, pitch);
  for (auto& q : x.q)
    if (problem.HasParameterBlock(q.data()))
      problem.SetManifold(q.data(), new ceres::EigenQuaternionManifold);
  const auto f = static_cast<std::size_t>(fixed);
  if (problem.HasParameterBlock(x.p[f].data())) {
    problem.SetParameterBlockConstant(x.p[f].data());
    problem.SetParameterBlockConstant(x.q[f].data());
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
  out.pitch_bias_rad = x.bias;
  for (std::size_t i = 0; i < poses.size(); ++i) poses[i] = x.pose(i);
  return out;
}

}  // namespace slamroute::evaluate
