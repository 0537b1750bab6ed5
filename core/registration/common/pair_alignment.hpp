#pragma once
// Manual fallback: the rigid transform that best aligns picked point pairs (source point i
// should land on target point i), least squares in closed form (Horn 1987 / Umeyama 1991:
// SVD of the cross-covariance of the centred pairs, no scale), with the residual of each pair
// so the user sees which pick is wrong.
//
// As surveyors work: pairs can be left out of the fit (a doubtful pick, or a check point kept
// to verify the result: its residual is still reported), and a levelled fit turns about the
// vertical only (4 degrees of freedom: yaw and shift), for scans whose tilt compensator already
// levelled them.
#include <Eigen/Core>

#include <span>
#include <vector>

#include "model/rigid_transform.hpp"

namespace plumb {

struct PairAlignmentParams {
  /// Pairs used by the fit (empty: all). Unused pairs keep their residuals (check points).
  std::vector<bool> used;
  /// Rotation about +Z only (levelled scans): needs 2 used pairs apart in plan; else >= 3
  /// non-collinear used pairs.
  bool levelled = false;
};

struct PairAlignmentResult {
  RigidTransform transform;        ///< source -> target
  std::vector<double> residuals;   ///< |T(source_i) - target_i|, metres, per pair (used or not)
  double rms = 0.0;                ///< metres, over the used pairs
  double check_rms = 0.0;          ///< metres, over the unused pairs (0 when none)
  std::size_t used = 0;            ///< pairs in the fit
};

/// Throws InputError naming the problem: sizes differ, too few used pairs, or their source (or
/// target) points collinear (levelled: coincident in plan).
PairAlignmentResult alignPointPairs(std::span<const Eigen::Vector3d> source,
                                    std::span<const Eigen::Vector3d> target,
                                    const PairAlignmentParams& params = {});

}  // namespace plumb
