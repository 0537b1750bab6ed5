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
};

}  // namespace plumb::refine_detail
