#pragma once
// Distance and overlap between two 3D segments (2023 §II, eqs. 1-6) with the fixes of
// docs/ALGORITHMS.md §5: the bisector direction is normalize(d_i + s d_j), s = sign(d_i·d_j), and
// the relative overlap is clamped to [0, 1].
#include <Eigen/Core>

namespace plumb {

struct SegmentPairMeasure {
  double relative_overlap = 0.0;  ///< eq. 3 / min(|s_i'|, |s_j'|), clamped to [0, 1]
  double distance = 0.0;          ///< eq. 4: mean of the midpoint-to-segment distances (m)
};

/// Eq. 5-6: distance from point g to segment [a, b] (projection clamped to the segment).
double pointSegmentDistance(const Eigen::Vector3d& g, const Eigen::Vector3d& a,
                            const Eigen::Vector3d& b);

/// Eqs. 1-4 for segments [a1 b1] and [a2 b2].
SegmentPairMeasure measureSegmentPair(const Eigen::Vector3d& a1, const Eigen::Vector3d& b1,
                                      const Eigen::Vector3d& a2, const Eigen::Vector3d& b2);

}  // namespace plumb
