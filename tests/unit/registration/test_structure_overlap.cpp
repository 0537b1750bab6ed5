// The structure overlap of refined placements (structure_overlap.hpp): the source points on its
// large planes only, measured where each placement lies, without moving it. A room placed in
// its copy of the target explains its floor and walls; the same room shifted by 0.3 m leaves
// part of them unexplained; a plane below the area limit is not structure.
#include <gtest/gtest.h>

#include "registration/auto/structure_overlap.hpp"

using namespace plumb;

namespace {

/// Points of one axis-aligned rectangle: x in [0, a], y in [0, b] mapped by `corner`, `u`, `v`.
void rectangle(PointCloud& c, PlanarPolygon& plane, const Eigen::Vector3d& corner,
               const Eigen::Vector3d& u, const Eigen::Vector3d& v, double step) {
  const double a = u.norm(), b = v.norm();
  for (double s = 0; s <= a; s += step)
    for (double t = 0; t <= b; t += step) {
      plane.inliers.push_back(static_cast<std::uint32_t>(c.positions.size()));
      c.positions.push_back((corner + s * u / a + t * v / b).cast<float>());
    }
  plane.area = a * b;
  plane.normal = u.cross(v).normalized();
}

struct Room {
  PointCloud cloud;
  std::vector<PlanarPolygon> planes;
};

/// A 4 x 5 x 2.6 m room: floor, two walls and a 1 x 1.2 m cupboard front (a small plane).
Room room() {
  Room r;
  const Eigen::Vector3d x = Eigen::Vector3d::UnitX(), y = Eigen::Vector3d::UnitY(),
                        z = Eigen::Vector3d::UnitZ();
  r.planes.resize(4);
  rectangle(r.cloud, r.planes[0], {0, 0, 0}, 4.0 * x, 5.0 * y, 0.05);
  rectangle(r.cloud, r.planes[1], {0, 0, 0}, 4.0 * x, 2.6 * z, 0.05);
  rectangle(r.cloud, r.planes[2], {0, 0, 0}, 5.0 * y, 2.6 * z, 0.05);
  rectangle(r.cloud, r.planes[3], {0.6, 1.0, 0}, 1.0 * y, 1.2 * z, 0.05);
  return r;
}

}  // namespace

TEST(StructureOverlap, OnlyLargePlanesAreStructure) {
  const Room r = room();
  const PointCloud s = structurePoints(r.cloud, r.planes, 4.0);
  const std::size_t small = r.planes[3].inliers.size();
  EXPECT_EQ(s.size(), r.cloud.size() - small);
  EXPECT_TRUE(structurePoints(r.cloud, r.planes, 50.0).empty());  // no plane that large
  EXPECT_TRUE(structurePoints(r.cloud, {}, 4.0).empty());
}

TEST(StructureOverlap, TheRightPlacementExplainsTheStructureAShiftedOneDoesNot) {
  const Room r = room();
  const RefineParams rp;
  const RefineTarget target(r.cloud, rp);
  std::vector<RefinedHypothesis> h(2);
  h[1].refined.transform = RigidTransform::fromYaw(0.0, {0.3, 0.0, 0.0});
  measureStructureOverlap(structurePoints(r.cloud, r.planes, 4.0), std::nullopt, target, rp, h);
  EXPECT_GT(h[0].refined.structure_overlap, 0.98);
  EXPECT_LT(h[1].refined.structure_overlap, h[0].refined.structure_overlap - 0.02);
  // No structure: nothing measured.
  std::vector<RefinedHypothesis> none(1);
  measureStructureOverlap(PointCloud{}, std::nullopt, target, rp, none);
  EXPECT_LT(none[0].refined.structure_overlap, 0.0);
}
