#pragma once
// Least-squares plane fitting and plane frames, shared by the feature extractors.
#include <Eigen/Core>

#include <cstdint>
#include <vector>

#include "model/feature_set.hpp"
#include "model/point_cloud.hpp"

namespace plumb {

/// Plane n·x = d fitted to points by PCA (normal = eigenvector of the smallest eigenvalue).
struct PlaneFit {
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  double offset = 0.0;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  double rms = 0.0;  ///< RMS point-to-plane distance
  bool valid = false;
};

/// Fits in the cloud's local coordinates (positions), indices given.
PlaneFit fitPlaneLocal(const PointCloud& cloud, const std::vector<std::uint32_t>& indices);
/// Fits from accumulated moments: count, sum of x, sum of x x^T (local coordinates).
PlaneFit fitPlaneFromMoments(double count, const Eigen::Vector3d& sum,
                             const Eigen::Matrix3d& sum_outer);

/// Sets origin/u_axis/v_axis of a polygon from its normal and centroid. Vertical planes get
/// v_axis = +Z and u_axis = Z x n (so u x v = n); others get u along the projection of X
/// (or Y) onto the plane.
void setPlaneFrame(PlanarPolygon& polygon);

}  // namespace plumb
