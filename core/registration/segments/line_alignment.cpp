#include "registration/segments/line_alignment.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

namespace plumb {

std::optional<Eigen::Vector3d> translationFromLines(const std::vector<PointLineConstraint>& c,
                                                    double min_eigenvalue) {
  Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
  Eigen::Vector3d w = Eigen::Vector3d::Zero();
  for (const auto& k : c) {
    const Eigen::Matrix3d a = Eigen::Matrix3d::Identity() - k.d * k.d.transpose();
    m += k.weight * a;                // M of eq. 14 (up to sign)
    w += k.weight * a * (k.a - k.p);  // w of eq. 14
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(m);
  const auto ev = es.eigenvalues();
  if (!(ev(2) > 0) || ev(0) < min_eigenvalue * ev(2)) return std::nullopt;
  return Eigen::Vector3d(m.ldlt().solve(w));  // eq. 14
}

LineAlignmentStep alignToLines(const std::vector<PointLineConstraint>& c,
                               const RigidTransform& current) {
  LineAlignmentStep out;
  out.transform = current;
  Eigen::Matrix<double, 6, 6> h = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 1> g = Eigen::Matrix<double, 6, 1>::Zero();
  for (const auto& k : c) {
    const Eigen::Vector3d q = current.rotation() * k.p;
    const Eigen::Matrix3d a = Eigen::Matrix3d::Identity() - k.d * k.d.transpose();
    const Eigen::Vector3d r = a * (q + current.translation() - k.a);
    Eigen::Matrix<double, 3, 6> j;
    // d(R p)/d(omega) = -[q]x for R <- exp([omega]x) R.
    j.leftCols<3>() << 0, q.z(), -q.y(), -q.z(), 0, q.x(), q.y(), -q.x(), 0;
    j.rightCols<3>().setIdentity();
    const Eigen::Matrix<double, 3, 6> aj = a * j;
    h += k.weight * aj.transpose() * aj;
    g += k.weight * aj.transpose() * r;
  }
  out.normal_matrix = h;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> es(h);
  if (!(es.eigenvalues()(5) > 0) || es.eigenvalues()(0) < 1e-9 * es.eigenvalues()(5)) return out;
  const Eigen::Matrix<double, 6, 1> delta = -h.ldlt().solve(g);
  const Eigen::Vector3d omega = delta.head<3>();
  const double angle = omega.norm();
  const Eigen::Matrix3d dr =
      angle > 0 ? Eigen::AngleAxisd(angle, omega / angle).toRotationMatrix()
                : Eigen::Matrix3d::Identity();
  // x' = dR (R p) + t + dt: the model linearised above.
  out.transform = RigidTransform(dr * current.rotation(), current.translation() + delta.tail<3>());
  out.ok = true;
  return out;
}

}  // namespace plumb
