#pragma once
// The surface the point-to-plane ICP matches source points against (docs/ALGORITHMS.md §8), in
// the refinement's local frame: the nearest target point with its estimated normal (a scan,
// or points sampled on a model), or the closest point on the model's triangles with the
// triangle's normal (triangle_target.hpp). Implementations are immutable and thread-safe.
#include <Eigen/Core>

namespace plumb::refine_detail {

class TargetSurface {
 public:
  virtual ~TargetSurface() = default;
  /// The surface point q nearest to x, at most `max_d` (m) away, and the unit normal n of the
  /// surface there; false when there is none (or it has no usable normal).
  virtual bool nearest(const Eigen::Vector3d& x, double max_d, Eigen::Vector3d& q,
                       Eigen::Vector3d& n) const = 0;
  /// As nearest, for a source point whose sensor stood at `viewer` (local frame, placed by the
  /// same pose). A surface that knows which side of it its own stations saw (a scan with sensor
  /// origins) keeps only points whose front side faces `viewer` too: a surface both stations
  /// saw (docs/ALGORITHMS.md §8). Default: nearest.
  virtual bool nearestSeenFrom(const Eigen::Vector3d& x, const Eigen::Vector3d& viewer, double max_d,
                               Eigen::Vector3d& q, Eigen::Vector3d& n) const {
    (void)viewer;
    return nearest(x, max_d, q, n);
  }
};

}  // namespace plumb::refine_detail
