#include "features/planes/plane_fit.hpp"

#include <Eigen/Eigenvalues>

#include <cmath>

namespace plumb {

PlaneFit fitPlaneFromMoments(double count, const Eigen::Vector3d& sum,
                             const Eigen::Matrix3d& sum_outer) {
  PlaneFit fit;
  if (count < 3) return fit;
  fit.centroid = sum / count;
  const Eigen::Matrix3d cov = sum_outer / count - fit.centroid * fit.centroid.transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  if (eig.info() != Eigen::Success) return fit;
  fit.normal = eig.eigenvectors().col(0).normalized();
  fit.offset = fit.normal.dot(fit.centroid);
  fit.rms = std::sqrt(std::max(0.0, eig.eigenvalues()(0)));
  fit.valid = std::isfinite(fit.offset) && eig.eigenvalues()(1) > 0.0;
  return fit;
}

PlaneFit fitPlaneLocal(const PointCloud& cloud, const std::vector<std::uint32_t>& indices) {
  // Two passes around a provisional centre keep float clouds precise.
  if (indices.empty()) return {};
  const Eigen::Vector3d c0 = cloud.positions[indices[0]].cast<double>();
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  Eigen::Matrix3d outer = Eigen::Matrix3d::Zero();
  for (auto i : indices) {
    const Eigen::Vector3d p = cloud.positions[i].cast<double>() - c0;
    sum += p;
    outer += p * p.transpose();
  }
  PlaneFit fit = fitPlaneFromMoments(static_cast<double>(indices.size()), sum, outer);
  fit.centroid += c0;
  fit.offset = fit.normal.dot(fit.centroid);
  return fit;
}

void setPlaneFrame(PlanarPolygon& polygon) {
  const Eigen::Vector3d n = polygon.normal.normalized();
  polygon.normal = n;
  polygon.origin = polygon.centroid - (n.dot(polygon.centroid) - polygon.offset) * n;
  if (std::abs(n.z()) < 0.7) {
    // Vertical-ish: v up (projection of Z), u = v x n so that u x v = n.
    Eigen::Vector3d v = Eigen::Vector3d::UnitZ() - n.z() * n;
    v.normalize();
    polygon.v_axis = v;
    polygon.u_axis = v.cross(n).normalized();
  } else {
    Eigen::Vector3d u = Eigen::Vector3d::UnitX() - n.x() * n;
    u.normalize();
    polygon.u_axis = u;
    polygon.v_axis = n.cross(u).normalized();
  }
}

}  // namespace plumb
