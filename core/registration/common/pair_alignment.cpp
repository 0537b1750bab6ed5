#include "registration/common/pair_alignment.hpp"

#include <Eigen/Geometry>
#include <Eigen/SVD>

#include <cmath>
#include <string>

#include "common/error.hpp"

namespace plumb {

namespace {

Eigen::Vector3d centroidOf(const std::vector<Eigen::Vector3d>& p) {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (const auto& x : p) c += x;
  return c / double(p.size());
}

/// Centroid and the second singular value of the centred points relative to the first: ~0 for
/// collinear (or coincident) points.
double spreadRatio(const std::vector<Eigen::Vector3d>& p, Eigen::Vector3d& centroid) {
  centroid = centroidOf(p);
  Eigen::MatrixXd m(p.size(), 3);
  for (std::size_t i = 0; i < p.size(); ++i) m.row(long(i)) = (p[i] - centroid).transpose();
  const Eigen::Vector3d s = Eigen::JacobiSVD<Eigen::MatrixXd>(m).singularValues();
  return s[0] > 0 ? s[1] / s[0] : 0.0;
}

/// Full rotation: cross-covariance H = sum (s_i - cs)(t_i - ct)^T, R = V diag(1,1,det) U^T
/// (Umeyama eq. 39-40).
RigidTransform fitFull(const std::vector<Eigen::Vector3d>& s, const std::vector<Eigen::Vector3d>& t) {
  if (s.size() < 3)
    throw InputError("point pairs: at least 3 pairs are needed in the fit, got " + std::to_string(s.size()));
  Eigen::Vector3d cs, ct;
  constexpr double kMinSpread = 1e-3;
  if (spreadRatio(s, cs) < kMinSpread)
    throw InputError("point pairs: the source points are collinear; pick points spread out");
  if (spreadRatio(t, ct) < kMinSpread)
    throw InputError("point pairs: the target points are collinear; pick points spread out");
  Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < s.size(); ++i) H += (s[i] - cs) * (t[i] - ct).transpose();
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(H, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d D = Eigen::Matrix3d::Identity();
  if ((svd.matrixV() * svd.matrixU().transpose()).determinant() < 0) D(2, 2) = -1.0;
  const Eigen::Matrix3d R = svd.matrixV() * D * svd.matrixU().transpose();
  return RigidTransform(R, ct - R * cs);
}

/// Rotation about +Z only: the yaw maximising sum (s_i' . t_i') of the centred plan vectors,
/// atan2(sum s x t, sum s . t) (the 2D case of the same least squares); shift from centroids.
RigidTransform fitLevelled(const std::vector<Eigen::Vector3d>& s, const std::vector<Eigen::Vector3d>& t) {
  if (s.size() < 2)
    throw InputError("point pairs: a levelled fit needs at least 2 pairs, got " + std::to_string(s.size()));
  const Eigen::Vector3d cs = centroidOf(s), ct = centroidOf(t);
  double cross = 0.0, dot = 0.0, spread_s = 0.0, spread_t = 0.0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const Eigen::Vector2d a = (s[i] - cs).head<2>(), b = (t[i] - ct).head<2>();
    cross += a.x() * b.y() - a.y() * b.x();
    dot += a.dot(b);
    spread_s += a.squaredNorm(), spread_t += b.squaredNorm();
  }
  constexpr double kMinPlanSpread = 1e-4;  // m^2: the picks must be apart in plan
  if (spread_s < kMinPlanSpread || spread_t < kMinPlanSpread)
    throw InputError("point pairs: the points coincide in plan; pick points apart horizontally");
  const Eigen::Matrix3d R = Eigen::AngleAxisd(std::atan2(cross, dot), Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return RigidTransform(R, ct - R * cs);
}

}  // namespace

PairAlignmentResult alignPointPairs(std::span<const Eigen::Vector3d> source,
                                    std::span<const Eigen::Vector3d> target,
                                    const PairAlignmentParams& params) {
  if (source.size() != target.size())
    throw InputError("point pairs: " + std::to_string(source.size()) + " source points but " +
                     std::to_string(target.size()) + " target points");
  if (!params.used.empty() && params.used.size() != source.size())
    throw InputError("point pairs: " + std::to_string(params.used.size()) + " use flags for " +
                     std::to_string(source.size()) + " pairs");
  const auto inFit = [&](std::size_t i) { return params.used.empty() || params.used[i]; };
  std::vector<Eigen::Vector3d> s, t;
  for (std::size_t i = 0; i < source.size(); ++i)
    if (inFit(i)) s.push_back(source[i]), t.push_back(target[i]);
  PairAlignmentResult r;
  r.transform = params.levelled ? fitLevelled(s, t) : fitFull(s, t);
  r.used = s.size();
  double fit2 = 0.0, check2 = 0.0;
  for (std::size_t i = 0; i < source.size(); ++i) {
    const double e = (r.transform.apply(source[i]) - target[i]).norm();
    r.residuals.push_back(e);
    (inFit(i) ? fit2 : check2) += e * e;
  }
  r.rms = std::sqrt(fit2 / double(r.used));
  const std::size_t checks = source.size() - r.used;
  r.check_rms = checks ? std::sqrt(check2 / double(checks)) : 0.0;
  return r;
}

}  // namespace plumb
