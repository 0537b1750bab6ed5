#include "report/feature_residuals.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace plumb::report {
namespace {

constexpr double kDeg = 180.0 / 3.14159265358979323846;

double angleBetweenAxes(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::acos(std::clamp(std::abs(a.normalized().dot(b.normalized())), 0.0, 1.0)) * kDeg;
}

/// Keeps the closest candidate within the limits.
void consider(FeatureResidual& r, double distance, double angle, const ResidualParams& p) {
  if (angle > p.max_angle_deg || distance > p.max_distance) return;
  if (r.matched && distance >= r.distance_m) return;
  r.matched = true;
  r.distance_m = distance;
  r.angle_deg = angle;
}

void planeResiduals(const FeatureSet& s, const FeatureSet& t, const RigidTransform& T,
                    const ResidualParams& p, std::vector<FeatureResidual>& out) {
  for (std::size_t i = 0; i < s.planes.size(); ++i) {
    PlanarPolygon moved = s.planes[i];
    moved.transform(T);
    FeatureResidual r{"plane", i, moved.area};
    for (const auto& q : t.planes)
      consider(r, std::abs(q.signedDistance(moved.centroid)), angleBetweenAxes(moved.normal, q.normal), p);
    out.push_back(r);
  }
}

Eigen::Vector3d centre(const Opening& o) {
  return 0.25 * (o.corners[0] + o.corners[1] + o.corners[2] + o.corners[3]);
}

Eigen::Vector3d normalOf(const Opening& o) {
  const Eigen::Vector3d n = (o.corners[1] - o.corners[0]).cross(o.corners[3] - o.corners[0]);
  return n.norm() > 0 ? n.normalized() : Eigen::Vector3d::UnitX();
}

void openingResiduals(const FeatureSet& s, const FeatureSet& t, const RigidTransform& T,
                      const ResidualParams& p, std::vector<FeatureResidual>& out) {
  for (std::size_t i = 0; i < s.openings.size(); ++i) {
    Opening moved = s.openings[i];
    moved.transform(T);
    const Eigen::Vector3d c = centre(moved), n = normalOf(moved);
    FeatureResidual r{"opening", i, moved.width() * moved.height()};
    for (const auto& q : t.openings) {
      const Eigen::Vector3d d = centre(q) - c;
      consider(r, (d - d.dot(n) * n).norm(), angleBetweenAxes(n, normalOf(q)), p);
    }
    out.push_back(r);
  }
}

double pointToSegment(const Eigen::Vector3d& x, const Segment3D& s) {
  const Eigen::Vector3d ab = s.b - s.a;
  const double len2 = ab.squaredNorm();
  const double u = len2 > 0 ? std::clamp((x - s.a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (s.a + u * ab - x).norm();
}

void segmentResiduals(const FeatureSet& s, const FeatureSet& t, const RigidTransform& T,
                      const ResidualParams& p, std::vector<FeatureResidual>& out) {
  std::vector<std::size_t> order(s.segments.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return s.segments[a].length() > s.segments[b].length();
  });
  order.resize(std::min(order.size(), p.max_segments));
  for (const std::size_t i : order) {
    Segment3D moved = s.segments[i];
    moved.transform(T);
    FeatureResidual r{"segment", i, moved.length()};
    for (const auto& q : t.segments)
      consider(r, pointToSegment(moved.midpoint(), q), angleBetweenAxes(moved.b - moved.a, q.b - q.a), p);
    out.push_back(r);
  }
}

}  // namespace

std::vector<FeatureResidual> featureResiduals(const FeatureSet& source, const FeatureSet& target,
                                              const RigidTransform& T, const ResidualParams& p) {
  std::vector<FeatureResidual> out;
  planeResiduals(source, target, T, p, out);
  openingResiduals(source, target, T, p, out);
  segmentResiduals(source, target, T, p, out);
  return out;
}

}  // namespace plumb::report
