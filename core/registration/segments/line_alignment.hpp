#pragma once
// Closed-form translation from point-to-line constraints (2023 eqs. 11-14) and its extension
// to a joint rotation + translation Gauss-Newton step, used to polish a hypothesis on every
// matched segment pair.
#include <Eigen/Core>

#include <optional>
#include <vector>

#include "model/rigid_transform.hpp"

namespace plumb {

/// Wants point p (source, already rotated) + t to lie on the line a + s d (target).
struct PointLineConstraint {
  Eigen::Vector3d p;
  Eigen::Vector3d a;
  Eigen::Vector3d d;  ///< unit
  double weight = 1.0;
};

/// Eqs. 11-14: t = (sum A_i)^-1 sum A_i (a_i - p_i) with A_i = [d_i]x^T [d_i]x = I - d_i d_i^T.
/// nullopt when sum A_i is singular (all lines parallel): smallest eigenvalue below
/// `min_eigenvalue` times the largest.
std::optional<Eigen::Vector3d> translationFromLines(const std::vector<PointLineConstraint>& c,
                                                    double min_eigenvalue = 1e-3);

/// One Gauss-Newton step of min sum w |A_i (R p_i + t - a_i)|^2 over a small rotation and the
/// translation, starting at `current`; constraints hold *unrotated* source points. Returns the
/// updated transform and the 6x6 normal matrix (rotation first).
struct LineAlignmentStep {
  RigidTransform transform;
  Eigen::Matrix<double, 6, 6> normal_matrix = Eigen::Matrix<double, 6, 6>::Zero();
  bool ok = false;
};
LineAlignmentStep alignToLines(const std::vector<PointLineConstraint>& c,
                               const RigidTransform& current);

}  // namespace plumb
