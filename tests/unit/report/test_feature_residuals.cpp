// Per-feature residuals: a known offset comes back, the wall thickness does not count.
#include <gtest/gtest.h>

#include "report/feature_residuals.hpp"

using namespace plumb;
using namespace plumb::report;

namespace {

PlanarPolygon wall(const Eigen::Vector3d& normal, double offset) {
  PlanarPolygon p;
  p.normal = normal.normalized();
  p.offset = offset;
  p.centroid = p.normal * offset;
  p.area = 10.0;
  return p;
}

Opening openingAt(double x, double y) {  // in the plane x = x, 1 m wide, 2 m high
  Opening o;
  o.corners = {Eigen::Vector3d(x, y, 0), Eigen::Vector3d(x, y + 1, 0), Eigen::Vector3d(x, y + 1, 2),
               Eigen::Vector3d(x, y, 2)};
  return o;
}

}  // namespace

TEST(FeatureResiduals, APlaneOffsetByFiveMillimetresReadsFiveMillimetres) {
  FeatureSet s, t;
  t.planes = {wall({1, 0, 0}, 4.0), wall({0, 1, 0}, 2.0)};
  s.planes = {wall({1, 0, 0}, 4.005), wall({0, 0, 1}, 9.0)};
  const auto r = featureResiduals(s, t, RigidTransform());
  ASSERT_EQ(r.size(), 2u);
  EXPECT_TRUE(r[0].matched);
  EXPECT_NEAR(r[0].distance_m, 0.005, 1e-9);
  EXPECT_NEAR(r[0].angle_deg, 0.0, 1e-6);
  EXPECT_FALSE(r[1].matched);  // no horizontal plane in the target
}

TEST(FeatureResidualsTransform, TheSourceIsMovedByTheTransformFirst) {
  FeatureSet s, t;
  t.planes = {wall({1, 0, 0}, 4.0)};
  s.planes = {wall({1, 0, 0}, 1.0)};
  const auto r = featureResiduals(s, t, RigidTransform(Eigen::Matrix3d::Identity(), Eigen::Vector3d(3.002, 0, 0)));
  ASSERT_TRUE(r[0].matched);
  EXPECT_NEAR(r[0].distance_m, 0.002, 1e-9);
}

TEST(FeatureResiduals, OpeningsAcrossTheWallCountOnlyTheirOffsetInTheFacade) {
  FeatureSet s, t;
  s.openings = {openingAt(0.0, 0.003)};  // indoor face, 3 mm along the wall
  t.openings = {openingAt(0.35, 0.0)};   // outdoor face, 35 cm away across the wall
  const auto r = featureResiduals(s, t, RigidTransform());
  ASSERT_EQ(r.size(), 1u);
  ASSERT_TRUE(r[0].matched);
  EXPECT_NEAR(r[0].distance_m, 0.003, 1e-9);
  EXPECT_NEAR(r[0].size, 2.0, 1e-12);
}

TEST(FeatureResiduals, SegmentsCompareMidpointsWithParallelSegments) {
  FeatureSet s, t;
  t.segments = {{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(4, 0, 0)}, {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0, 4, 0)}};
  s.segments = {{Eigen::Vector3d(1, 0.004, 0), Eigen::Vector3d(3, 0.004, 0)}};
  const auto r = featureResiduals(s, t, RigidTransform());
  ASSERT_EQ(r.size(), 1u);
  ASSERT_TRUE(r[0].matched);
  EXPECT_NEAR(r[0].distance_m, 0.004, 1e-9);
  EXPECT_NEAR(r[0].size, 2.0, 1e-12);
}
