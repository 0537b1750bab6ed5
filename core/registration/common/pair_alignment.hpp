#pragma once
// Manual fallback: the rigid transform that best aligns picked point pairs (source point i
// should land on target point i), least squares in closed form (Horn 1987 / Umeyama 1991:
// SVD of the cross-covariance of the centred pairs, no scale), with the residual of each pair
// so the user sees which pick is wrong.
#include <Eigen/Core>

#include <span>
#include <vector>

#include "model/rigid_transform.hpp"

namespace plumb {

struct PairAlignmentResult {
  RigidTransform transform;        ///< source -> target
  std::vector<double> residuals;   ///< |T(source_i) - target_i|, metres, per pair
  double rms = 0.0;                ///< metres
};

/// Needs >= 3 pairs whose source points (and target points) are not collinear; throws
/// InputError naming the problem otherwise.
PairAlignmentResult alignPointPairs(std::span<const Eigen::Vector3d> source,
                                    std::span<const Eigen::Vector3d> target);

}  // namespace plumb
