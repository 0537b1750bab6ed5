#include <algorithm>
#include <cmath>

#include "common/error.hpp"
#include "simulation/mms_scanner.hpp"

namespace plumb {

Trajectory streetTrajectory(const std::vector<Eigen::Vector3d>& outline, const MmsParams& params, double t0) {
  // Convex hull (monotone chain, counter-clockwise) of the outline: the streets around the block.
  std::vector<Eigen::Vector2d> pts;
  for (const auto& p : outline) pts.emplace_back(p.x(), p.y());
  std::sort(pts.begin(), pts.end(), [](const auto& a, const auto& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
  auto cross = [](const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x();
  };
  std::vector<Eigen::Vector2d> hull(2 * pts.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], pts[i]) <= 1e-12) --k;
    hull[k++] = pts[i];
  }
  for (std::size_t i = pts.size() - 1, lo = k + 1; i-- > 0;) {
    while (k >= lo && cross(hull[k - 2], hull[k - 1], pts[i]) <= 1e-12) --k;
    hull[k++] = pts[i];
  }
  hull.resize(k > 0 ? k - 1 : 0);
  if (hull.size() < 3) throw InputError("street trajectory: the building outline needs 3 non-collinear corners");
  // Offset each corner outwards (mitre) by street_offset.
  Trajectory traj;
  const std::size_t n = hull.size();
  const double d = params.street_offset;
  for (std::size_t i = 0; i <= n; ++i) {
    const auto& a = hull[(i + n - 1) % n];
    const auto& b = hull[i % n];
    const auto& c = hull[(i + 1) % n];
    const Eigen::Vector2d e1 = (b - a).normalized(), e2 = (c - b).normalized();
    const Eigen::Vector2d n1(e1.y(), -e1.x()), n2(e2.y(), -e2.x());
    const Eigen::Vector2d p = b + d * (n1 + n2) / (1.0 + n1.dot(n2));
    const Eigen::Vector3d pos(p.x(), p.y(), params.sensor_height + (outline.empty() ? 0.0 : outline[0].z()));
    const double t = traj.positions.empty() ? t0 : traj.times.back() + (pos - traj.positions.back()).norm() / params.speed;
    traj.positions.push_back(pos);
    traj.times.push_back(t);
  }
  return traj;
}

}  // namespace plumb
