#include "registration/segment_distance/segment_pair_distance.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace plumb {

double pointSegmentDistance(const Eigen::Vector3d& g, const Eigen::Vector3d& a,
                            const Eigen::Vector3d& b) {
  const Eigen::Vector3d ab = b - a;
  const double l2 = ab.squaredNorm();
  if (l2 <= 0) return (g - a).norm();
  // Eq. 6: projection on the line, clamped to [A, B].
  const double s = std::clamp((g - a).dot(ab) / l2, 0.0, 1.0);
  return (g - (a + s * ab)).norm();  // eq. 5
}

SegmentPairMeasure measureSegmentPair(const Eigen::Vector3d& a1, const Eigen::Vector3d& b1,
                                      const Eigen::Vector3d& a2, const Eigen::Vector3d& b2) {
  SegmentPairMeasure m;
  Eigen::Vector3d d1 = b1 - a1, d2 = b2 - a2;
  const double l1 = d1.norm(), l2 = d2.norm();
  if (l1 <= 0 || l2 <= 0) return m;
  d1 /= l1;
  d2 /= l2;
  // Bisector line through the barycentre of the 4 endpoints (Fig. 1); direction
  // normalize(d1 + s d2) (docs/ALGORITHMS.md §5 fix of the paper's (d_i + d_j)/2).
  const double s = d1.dot(d2) >= 0 ? 1.0 : -1.0;
  Eigen::Vector3d v = d1 + s * d2;
  const double vn = v.norm();
  v = vn > 1e-12 ? Eigen::Vector3d(v / vn) : d1;
  const Eigen::Vector3d p = 0.25 * (a1 + b1 + a2 + b2);
  // Eq. 1: abscissae c_ij(P) = (P - P_ij)·v.
  const double ca1 = (a1 - p).dot(v), cb1 = (b1 - p).dot(v);
  const double ca2 = (a2 - p).dot(v), cb2 = (b2 - p).dot(v);
  const double len1 = std::abs(ca1 - cb1), len2 = std::abs(ca2 - cb2);  // eq. 2
  const double overlap = std::min(std::max(ca1, cb1), std::max(ca2, cb2)) -
                         std::max(std::min(ca1, cb1), std::min(ca2, cb2));  // eq. 3
  const double shorter = std::min(len1, len2);
  m.relative_overlap = shorter > 0 ? std::clamp(overlap / shorter, 0.0, 1.0) : 0.0;
  // Eq. 4: mean of the distances of each midpoint to the other segment.
  m.distance = 0.5 * (pointSegmentDistance(0.5 * (a1 + b1), a2, b2) +
                      pointSegmentDistance(0.5 * (a2 + b2), a1, b1));
  return m;
}

}  // namespace plumb
