#pragma once
// The global adjustment of a network of station poses (docs/NETWORK.md "Cost function"): each
// station i has a pose X_i (station frame -> reference frame), each edge (a, b) a measured
// relative pose T_ab (b's frame -> a's frame, from the link registration) with standard
// deviations. Ceres minimises
//   sum over edges of rho( |W_ab r_ab|^2 ),  r_ab = [ R_a^T (t_b - t_a) - t_ab ;
//                                                    2 vec( q_ab * (q_a^-1 q_b)^-1 ) ]
// with W_ab = diag(1/sigma_t x3, 1/sigma_r x3) and rho the Cauchy loss of scale s
// (rho(x) = s^2 log(1 + x / s^2)), the reference station held fixed. The covariance of each
// pose comes from Ceres' Covariance at the optimum (links weighted as the robust loss leaves them).
#include <cstddef>
#include <string>
#include <vector>

#include "model/rigid_transform.hpp"

namespace plumb {

struct PoseGraphEdge {
  std::size_t a = 0, b = 0;
  RigidTransform measured;   ///< b's frame -> a's frame
  double sigma_translation = 0.001;  ///< m
  double sigma_rotation = 1e-4;      ///< rad
};

/// A point seen by a station whose coordinates in the reference frame are known (a control
/// point's target): r = (R_s p + t_s - target) / sigma.
struct PointConstraint {
  std::size_t station = 0;
  Eigen::Vector3d observed = Eigen::Vector3d::Zero();  ///< in the station's frame
  Eigen::Vector3d target = Eigen::Vector3d::Zero();    ///< in the reference frame
  double sigma = 0.002;                                ///< m, per coordinate
};

struct PoseGraphProblem {
  std::vector<RigidTransform> initial;  ///< per station, station -> reference frame
  std::size_t reference = 0;            ///< held fixed at its initial pose (fix_reference)
  /// Off when point constraints fix the frame (control points): no station is held.
  bool fix_reference = true;
  /// More stations held at their initial pose (stations the surveyor locked).
  std::vector<std::size_t> fixed;
  std::vector<PointConstraint> points;  ///< least squares, no robust loss
  std::vector<PoseGraphEdge> edges;     ///< stations in no edge keep their initial pose
  double robust_scale = 3.0;            ///< Cauchy scale on the normalised residual; <= 0: none
  int max_iterations = 200;
};

struct EdgeResidual {
  double translation = 0.0;  ///< m, |t| of T_ab^-1 X_a^-1 X_b
  double rotation_deg = 0.0; ///< angle of the same
  double normalised = 0.0;   ///< |W r|, in standard deviations
};

struct PoseGraphSolution {
  std::vector<RigidTransform> poses;
  /// Per station: standard deviations of the position (x, y, z, m) and of the rotation about
  /// the reference frame's axes (deg); zero for a fixed reference and stations in no edge.
  std::vector<Eigen::Vector3d> sigma_position, sigma_rotation_deg;
  std::vector<EdgeResidual> residuals;  ///< per edge, at the solution
  bool converged = false;
  bool covariance_ok = false;
  int iterations = 0;
  double initial_cost = 0.0, final_cost = 0.0;
  std::string message;
};

/// Residual of one edge for given poses.
EdgeResidual edgeResidual(const PoseGraphEdge& e, const RigidTransform& pose_a, const RigidTransform& pose_b);

/// Solves the problem (deterministic: single-threaded dense/sparse Cholesky).
PoseGraphSolution solvePoseGraph(const PoseGraphProblem& problem);

}  // namespace plumb
