#include "registration/common/pair_alignment.hpp"

#include <Eigen/Geometry>
#include <Eigen/SVD>

#include <cmath>
#include <string>

#include "common/error.hpp"

namespace plumb {

namespace {

/// Centroid and the second singular value of the centred points relative to the first: ~0 for
/// collinear (or coincident) points.
double spreadRatio(std::span<const Eigen::Vector3d> p, Eigen::Vector3d& centroid) {
  centroid.setZero();
  for (const auto& x : p) centroid += x;
  centroid /= double(p.size());
  Eigen::MatrixXd m(p.size(), 3);
  for (std::size_t i = 0; i < p.size(); ++i) m.row(long(i)) = (p[i] - centroid).transpose();
  const Eigen::Vector3d s = Eigen::JacobiSVD<Eigen::MatrixXd>(m).singularValues();
  return s[0] > 0 ? s[1] / s[0] : 0.0;
}

}  // namespace

PairAlignmentResult alignPointPairs(std::span<const Eigen::Vector3d> source,
                                    std::span<const Eigen::Vector3d> target) {
  if (source.size() != target.size())
    throw InputError("point pairs: " + std::to_string(source.size()) + " source points but " +
                     std::to_string(target.size()) + " target points");
  if (source.size() < 3)
    throw InputError("point pairs: at least 3 pairs are needed, got " +
                     std::to_string(source.size()));
  Eigen::Vector3d cs, ct;
  constexpr double kMinSpread = 1e-3;
  if (spreadRatio(source, cs) < kMinSpread)
    throw InputError("point pairs: the source points are collinear; pick points spread out");
  if (spreadRatio(target, ct) < kMinSpread)
    throw InputError("point pairs: the target points are collinear; pick points spread out");
  // Cross-covariance H = sum (s_i - cs)(t_i - ct)^T; R = V diag(1,1,det) U^T (Umeyama eq. 39-40).
  Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < source.size(); ++i) H += (source[i] - cs) * (target[i] - ct).transpose();
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(H, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d D = Eigen::Matrix3d::Identity();
  if ((svd.matrixV() * svd.matrixU().transpose()).determinant() < 0) D(2, 2) = -1.0;
  const Eigen::Matrix3d R = svd.matrixV() * D * svd.matrixU().transpose();
  PairAlignmentResult r;
  r.transform = RigidTransform(R, ct - R * cs);
  double sum2 = 0.0;
  for (std::size_t i = 0; i < source.size(); ++i) {
    r.residuals.push_back((r.transform.apply(source[i]) - target[i]).norm());
    sum2 += r.residuals.back() * r.residuals.back();
  }
  r.rms = std::sqrt(sum2 / double(source.size()));
  return r;
}

}  // namespace plumb
