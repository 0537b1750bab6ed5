#include "model/feature_set.hpp"

#include <cmath>

namespace plumb {

bool PlanarPolygon::isVertical(double tolerance_deg) const {
  return std::abs(normal.z()) <= std::sin(tolerance_deg * M_PI / 180.0);
}

bool PlanarPolygon::isHorizontal(double tolerance_deg) const {
  return std::abs(normal.z()) >= std::cos(tolerance_deg * M_PI / 180.0);
}

void PlanarPolygon::transform(const RigidTransform& t) {
  // n' = R n, d' = d + n'·t (docs/ALGORITHMS.md "Frames").
  normal = t.rotation() * normal;
  offset += normal.dot(t.translation());
  centroid = t.apply(centroid);
  origin = t.apply(origin);
  u_axis = t.rotation() * u_axis;
  v_axis = t.rotation() * v_axis;
}

std::array<Segment3D, 4> Opening::edges() const {
  std::array<Segment3D, 4> e;
  for (int i = 0; i < 4; ++i) {
    e[i].a = corners[i];
    e[i].b = corners[(i + 1) % 4];
  }
  return e;
}

void FeatureSet::transform(const RigidTransform& t) {
  for (auto& p : planes) p.transform(t);
  for (auto& o : openings) o.transform(t);
  for (auto& s : segments) s.transform(t);
}

Bounds featureBounds(const FeatureSet& f) {
  Bounds b;
  for (const auto& p : f.planes)
    for (const auto& ring : p.rings)
      for (const auto& uv : ring) b.extend(p.to3d(uv));
  for (const auto& o : f.openings)
    for (const auto& c : o.corners) b.extend(c);
  for (const auto& s : f.segments) {
    b.extend(s.a);
    b.extend(s.b);
  }
  return b;
}

}  // namespace plumb
