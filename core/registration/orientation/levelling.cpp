#include "registration/orientation/levelling.hpp"

#include <Eigen/Geometry>

#include "features/planes/plane_fit.hpp"

namespace plumb {

namespace {
RigidTransform aboutCentre(const Eigen::Matrix3d& r, const Eigen::Vector3d& centre) {
  return RigidTransform(r, centre - r * centre);  // x' = r (x - c) + c
}
}  // namespace

RigidTransform levellingTransform(const Eigen::Vector3d& up, const Eigen::Vector3d& centre) {
  const Eigen::Vector3d u = up.normalized();
  Eigen::Matrix3d r;
  if (u.dot(Eigen::Vector3d::UnitZ()) < -1.0 + 1e-12)
    r = Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitX()).toRotationMatrix();
  else
    r = Eigen::Quaterniond::FromTwoVectors(u, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return aboutCentre(r, centre);
}

RigidTransform yUpLevelling(const Eigen::Vector3d& centre) {
  return aboutCentre(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()).toRotationMatrix(),
                     centre);
}

void levelPolygon(PlanarPolygon& polygon, const RigidTransform& l) {
  polygon.transform(l);
  const PlanarPolygon moved = polygon;  // the old frame, moved rigidly
  setPlaneFrame(polygon);
  // Both frames are right-handed about the same normal: an in-plane rotation, ring
  // orientations (outer counter-clockwise, holes clockwise) are kept.
  for (auto& ring : polygon.rings)
    for (auto& q : ring) q = polygon.to2d(moved.to3d(q));
}

}  // namespace plumb
