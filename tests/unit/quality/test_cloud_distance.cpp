#include <gtest/gtest.h>

#include <cmath>

#include "common/error.hpp"
#include "quality/cloud_distance.hpp"

using namespace plumb;

namespace {

/// A 10 m x 10 m grid of points in the plane z = z0, spacing 0.1 m, around a large offset.
PointCloud grid(double z0, const Eigen::Vector3d& offset) {
  PointCloud c;
  c.offset = offset;
  for (int i = 0; i <= 100; ++i)
    for (int j = 0; j <= 100; ++j) c.positions.emplace_back(i * 0.1f, j * 0.1f, float(z0));
  return c;
}

}  // namespace

TEST(CloudDistance, ParallelPlanesGiveTheirSeparationThroughTransforms) {
  const Eigen::Vector3d offset(651234.0, 6862345.0, 40.0);  // Lambert-93-like coordinates
  const PointCloud target = grid(0.0, offset);
  // The source is the same grid 2 cm above, but stored rotated by 30 deg about a vertical axis
  // through the offset and shifted: its transform to world brings it back.
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.5236, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const RigidTransform moved(R, offset - R * offset + Eigen::Vector3d(3.0, -2.0, 1.0));
  PointCloud source = grid(0.02, offset);
  source.transform(moved);
  const DistanceResult r = cloudToCloudDistances(source, moved.inverse(), target, {}, {});
  ASSERT_EQ(r.distances.size(), source.size());
  EXPECT_EQ(r.matched, source.size());
  EXPECT_NEAR(r.median, 0.02, 1e-3);
  EXPECT_NEAR(r.mean, 0.02, 1e-3);
  EXPECT_NEAR(r.p95, 0.02, 1e-3);
}

TEST(CloudDistance, FarPointsAreUnmatched) {
  const PointCloud target = grid(0.0, Eigen::Vector3d::Zero());
  PointCloud source = grid(0.0, Eigen::Vector3d::Zero());
  source.positions[0].z() = 5.0f;  // 5 m above: beyond the 0.1 m default radius
  const DistanceResult r = cloudToCloudDistances(source, {}, target, {}, {});
  EXPECT_TRUE(std::isnan(r.distances[0]));
  EXPECT_EQ(r.matched, source.size() - 1);
  EXPECT_NEAR(r.mean, 0.0, 1e-6);
  DistanceParams wide;
  wide.max_distance = 10.0;
  EXPECT_NEAR(cloudToCloudDistances(source, {}, target, {}, wide).distances[0], 5.0, 1e-5);
}

TEST(CloudDistance, CloudToMeshMeasuresToTheTriangleNotItsVertices) {
  // One 100 m x 100 m square (2 triangles): vertices are far, the surface is 3 cm away.
  TriangleMesh mesh;
  mesh.vertices = {{-50, -50, 0}, {50, -50, 0}, {50, 50, 0}, {-50, 50, 0}};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  PointCloud source = grid(0.03, Eigen::Vector3d(-5, -5, 0));
  const DistanceResult r = cloudToMeshDistances(source, {}, mesh, {}, {});
  EXPECT_EQ(r.matched, source.size());
  EXPECT_NEAR(r.median, 0.03, 1e-5);
  // Moving the mesh up by 3 cm (its transform) brings the distances to zero.
  const DistanceResult on = cloudToMeshDistances(source, {}, mesh,
                                                 RigidTransform(Eigen::Matrix3d::Identity(),
                                                                Eigen::Vector3d(0, 0, 0.03)), {});
  EXPECT_LT(on.p95, 1e-5);
  EXPECT_THROW(cloudToMeshDistances(source, {}, TriangleMesh{}, {}, {}), InputError);
}

TEST(CloudDistance, HistogramCountsEveryValueOnce) {
  const std::vector<float> v{0.0f, 0.015f, 0.019f, 0.05f, 0.099f, 0.1f, 0.5f, -0.1f,
                             std::numeric_limits<float>::quiet_NaN()};
  const DistanceHistogram h = distanceHistogram(v, 0.0, 0.1, 10);
  ASSERT_EQ(h.counts.size(), 10u);
  EXPECT_EQ(h.counts[0], 1u);
  EXPECT_EQ(h.counts[1], 2u);
  EXPECT_EQ(h.counts[5], 1u);
  EXPECT_EQ(h.counts[9], 1u);
  EXPECT_EQ(h.above, 2u);
  EXPECT_EQ(h.below, 1u);
  EXPECT_EQ(h.invalid, 1u);
  EXPECT_DOUBLE_EQ(h.binWidth(), 0.01);
  EXPECT_THROW(distanceHistogram(v, 0.1, 0.1, 10), InputError);
}
