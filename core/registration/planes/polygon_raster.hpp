#pragma once
// Raster approximation of a planar polygon (outer ring + holes) in its own (u, v) frame, used
// for the overlap areas of the 2021 score (eq. 10). A polygon is rasterised once; the overlap
// with another polygon under any hypothesis costs one lookup per sample of the smaller one.
// Accuracy against exact polygon Boolean operations is checked in the unit tests (< 1%).
#include <Eigen/Core>

#include <cstdint>
#include <vector>

#include "model/feature_set.hpp"
#include "model/rigid_transform.hpp"

namespace plumb {

class PolygonRaster {
 public:
  /// `cells_across`: cells along the longer side of the bounding box, [16, 4096].
  /// `max_samples`: inside-cell centres kept for sampling (a regular subset), [64, 1e6].
  PolygonRaster(const PlanarPolygon& polygon, int cells_across = 256, int max_samples = 4000);

  /// True when the (u, v) point of the polygon frame is inside (outer ring minus holes).
  bool inside(const Eigen::Vector2d& uv) const;
  /// Orthogonal projection of a world point into the polygon's (u, v) frame.
  Eigen::Vector2d project(const Eigen::Vector3d& p) const {
    const Eigen::Vector3d q = p - origin_;
    return {q.dot(u_), q.dot(v_)};
  }
  /// Area covered by the raster (close to the polygon area), m^2.
  double area() const { return area_; }
  /// World positions of sample points (centres of inside cells) and the area each stands for.
  const std::vector<Eigen::Vector3d>& samples() const { return samples_; }
  double sampleArea() const { return sample_area_; }
  /// A regular subset of at most ~64 samples for fast pre-scoring, and its area per sample.
  const std::vector<Eigen::Vector3d>& coarseSamples() const { return coarse_; }
  double coarseSampleArea() const { return coarse_area_; }
  double radius() const { return radius_; }  ///< bounding radius about centre()
  const Eigen::Vector3d& centre() const { return centre_; }

 private:
  Eigen::Vector2d lo_;
  double cell_ = 1.0;
  int nu_ = 0, nv_ = 0;
  std::vector<std::uint8_t> mask_;
  std::vector<Eigen::Vector3d> samples_, coarse_;
  double coarse_area_ = 0.0;
  double area_ = 0.0, sample_area_ = 0.0, radius_ = 0.0;
  Eigen::Vector3d centre_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d origin_, u_, v_;
};

/// Area of the intersection of polygon `a` mapped by `t` with polygon `b`, both projected on
/// b's plane (for near-parallel planes this equals the projection on their bisector plane up to
/// a factor cos(angle) >= 0.98 within the clustering tolerance). m^2.
/// `coarse` uses the coarse samples (pre-scoring of many hypotheses).
double overlapArea(const PolygonRaster& a, const PolygonRaster& b, const RigidTransform& t,
                   bool coarse = false);

}  // namespace plumb
