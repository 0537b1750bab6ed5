#include "registration/network/pose_graph.hpp"

#include <ceres/ceres.h>

#include <Eigen/Geometry>
#include <cmath>
#include <algorithm>
#include <memory>

namespace plumb {
namespace {

/// r = W [ R_a^T (t_b - t_a) - t_ab ; 2 vec(q_ab * (q_a^-1 q_b)^-1) ] (header comment).
struct RelativePoseCost {
  Eigen::Quaterniond q_ab;
  Eigen::Vector3d t_ab;
  double w_t, w_r;

  template <class T>
  bool operator()(const T* qa_p, const T* ta_p, const T* qb_p, const T* tb_p, T* r) const {
    const Eigen::Map<const Eigen::Quaternion<T>> qa(qa_p), qb(qb_p);
    const Eigen::Map<const Eigen::Matrix<T, 3, 1>> ta(ta_p), tb(tb_p);
    const Eigen::Quaternion<T> qa_inv = qa.conjugate();
    const Eigen::Quaternion<T> q_est = qa_inv * qb;
    const Eigen::Matrix<T, 3, 1> t_est = qa_inv * (tb - ta);
    const Eigen::Quaternion<T> dq = q_ab.template cast<T>() * q_est.conjugate();
    for (int k = 0; k < 3; ++k) {
      r[k] = T(w_t) * (t_est[k] - T(t_ab[k]));
      r[3 + k] = T(w_r) * T(2.0) * dq.vec()[k];
    }
    return true;
  }
};

/// r = (R_s p + t_s - target) / sigma (PointConstraint).
struct PointCost {
  Eigen::Vector3d p, target;
  double w;

  template <class T>
  bool operator()(const T* q_p, const T* t_p, T* r) const {
    const Eigen::Map<const Eigen::Quaternion<T>> q(q_p);
    const Eigen::Map<const Eigen::Matrix<T, 3, 1>> t(t_p);
    const Eigen::Matrix<T, 3, 1> x = q * p.cast<T>() + t;
    for (int k = 0; k < 3; ++k) r[k] = T(w) * (x[k] - T(target[k]));
    return true;
  }
};

struct PoseBlocks {
  std::vector<Eigen::Quaterniond> q;  // coefficients x, y, z, w (Eigen order)
  std::vector<Eigen::Vector3d> t;
};

PoseBlocks blocksFrom(const std::vector<RigidTransform>& poses) {
  PoseBlocks b;
  for (const auto& p : poses) {
    b.q.push_back(p.quaternion().normalized());
    b.t.push_back(p.translation());
  }
  return b;
}

/// Station i keeps its initial pose: the fixed reference, or a locked station.
bool isHeld(const PoseGraphProblem& in, std::size_t i) {
  return (in.fix_reference && i == in.reference) || std::find(in.fixed.begin(), in.fixed.end(), i) != in.fixed.end();
}

void addEdges(ceres::Problem& problem, PoseBlocks& b, const PoseGraphProblem& in) {
  for (const auto& e : in.edges) {
    auto* cost = new ceres::AutoDiffCostFunction<RelativePoseCost, 6, 4, 3, 4, 3>(new RelativePoseCost{
        e.measured.quaternion().normalized(), e.measured.translation(), 1.0 / e.sigma_translation,
        1.0 / e.sigma_rotation});
    ceres::LossFunction* loss =
        in.robust_scale > 0 ? new ceres::CauchyLoss(in.robust_scale) : nullptr;
    problem.AddResidualBlock(cost, loss, b.q[e.a].coeffs().data(), b.t[e.a].data(), b.q[e.b].coeffs().data(),
                             b.t[e.b].data());
  }
  for (const auto& c : in.points)
    problem.AddResidualBlock(
        new ceres::AutoDiffCostFunction<PointCost, 3, 4, 3>(new PointCost{c.observed, c.target, 1.0 / c.sigma}),
        nullptr, b.q[c.station].coeffs().data(), b.t[c.station].data());
  for (std::size_t i = 0; i < b.q.size(); ++i) {
    if (!problem.HasParameterBlock(b.q[i].coeffs().data())) continue;
    problem.SetManifold(b.q[i].coeffs().data(), new ceres::EigenQuaternionManifold);
    if (isHeld(in, i)) {
      problem.SetParameterBlockConstant(b.q[i].coeffs().data());
      problem.SetParameterBlockConstant(b.t[i].data());
    }
  }
}

/// Ceres' quaternion tangent delta d rotates by 2|d|: rotation sigma = 2 sqrt(diag).
void stationCovariances(ceres::Problem& problem, PoseBlocks& b, const PoseGraphProblem& in,
                        PoseGraphSolution& out) {
  ceres::Covariance::Options options;
  options.algorithm_type = ceres::DENSE_SVD;
  options.null_space_rank = -1;
  ceres::Covariance covariance(options);
  std::vector<std::pair<const double*, const double*>> blocks;
  for (std::size_t i = 0; i < b.q.size(); ++i)
    if (!isHeld(in, i) && problem.HasParameterBlock(b.t[i].data())) {
      blocks.emplace_back(b.q[i].coeffs().data(), b.q[i].coeffs().data());
      blocks.emplace_back(b.t[i].data(), b.t[i].data());
    }
  if (blocks.empty() || !covariance.Compute(blocks, &problem)) return;
  out.covariance_ok = true;
  for (std::size_t i = 0; i < b.q.size(); ++i) {
    if (isHeld(in, i) || !problem.HasParameterBlock(b.t[i].data())) continue;
    Eigen::Matrix3d ct, cr;
    covariance.GetCovarianceBlock(b.t[i].data(), b.t[i].data(), ct.data());
    covariance.GetCovarianceBlockInTangentSpace(b.q[i].coeffs().data(), b.q[i].coeffs().data(), cr.data());
    out.sigma_position[i] = ct.diagonal().cwiseMax(0.0).cwiseSqrt();
    out.sigma_rotation_deg[i] = 2.0 * cr.diagonal().cwiseMax(0.0).cwiseSqrt() * 180.0 / M_PI;
  }
}

}  // namespace

EdgeResidual edgeResidual(const PoseGraphEdge& e, const RigidTransform& pose_a, const RigidTransform& pose_b) {
  const RigidTransform d = e.measured.inverse() * pose_a.inverse() * pose_b;
  EdgeResidual r;
  r.translation = d.translation().norm();
  r.rotation_deg = d.rotationAngleDeg();
  const Eigen::Vector3d rt = (pose_a.rotation().transpose() * (pose_b.translation() - pose_a.translation()) -
                              e.measured.translation()) / e.sigma_translation;
  const double rr = r.rotation_deg * M_PI / 180.0 / e.sigma_rotation;
  r.normalised = std::sqrt(rt.squaredNorm() + rr * rr);
  return r;
}

PoseGraphSolution solvePoseGraph(const PoseGraphProblem& in) {
  PoseGraphSolution out;
  const std::size_t n = in.initial.size();
  out.poses = in.initial;
  out.sigma_position.assign(n, Eigen::Vector3d::Zero());
  out.sigma_rotation_deg.assign(n, Eigen::Vector3d::Zero());
  PoseBlocks b = blocksFrom(in.initial);
  ceres::Problem problem;
  addEdges(problem, b, in);
  if (!in.edges.empty() || !in.points.empty()) {
    ceres::Solver::Options options;
    options.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
    options.max_num_iterations = in.max_iterations;
    options.num_threads = 1;
    options.function_tolerance = 1e-12;
    options.parameter_tolerance = 1e-12;
    ceres::Solver::Summary summary;
    ceres::Solve(options, &problem, &summary);
    out.converged = summary.termination_type == ceres::CONVERGENCE;
    out.iterations = static_cast<int>(summary.iterations.size());
    out.initial_cost = summary.initial_cost;
    out.final_cost = summary.final_cost;
    out.message = summary.BriefReport();
    for (std::size_t i = 0; i < n; ++i)
      if (problem.HasParameterBlock(b.t[i].data()))
        out.poses[i] = RigidTransform::fromQuaternion(b.q[i].normalized(), b.t[i]);
    stationCovariances(problem, b, in, out);
  }
  for (const auto& e : in.edges) out.residuals.push_back(edgeResidual(e, out.poses[e.a], out.poses[e.b]));
  return out;
}

}  // namespace plumb
