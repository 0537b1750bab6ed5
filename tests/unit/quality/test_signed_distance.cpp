// Signed distances (issue 17): the sign convention of core/quality/cloud_distance.hpp on known
// geometry, unmatched and non-finite points, and the "distance" field a dataset exports.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "common/error.hpp"
#include "quality/cloud_distance.hpp"

using namespace plumb;

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

/// A 4 m x 4 m grid in the plane z = 0, spacing 5 cm, around `offset`.
PointCloud floorGrid(const Eigen::Vector3d& offset = Eigen::Vector3d::Zero()) {
  PointCloud c;
  c.offset = offset;
  for (int i = -40; i <= 40; ++i)
    for (int j = -40; j <= 40; ++j) c.positions.emplace_back(i * 0.05f, j * 0.05f, 0.0f);
  return c;
}

/// Points over grid nodes at the given heights (local coordinates, same offset).
PointCloud pointsAt(const std::vector<float>& heights, const Eigen::Vector3d& offset = Eigen::Vector3d::Zero()) {
  PointCloud c;
  c.offset = offset;
  for (std::size_t k = 0; k < heights.size(); ++k)
    c.positions.emplace_back(0.05f * float(k % 7), -0.05f * float(k % 5), heights[k]);
  return c;
}

void setOrigins(PointCloud& c, const Eigen::Vector3f& origin) { c.sensor_origins.assign(c.size(), origin); }

}  // namespace

TEST(SignedDistance, FiveMillimetresInFrontOfAndBehindAPlaneFacingItsScanner) {
  PointCloud target = floorGrid();
  setOrigins(target, {0, 0, 1.6f});  // the scanner stands above the floor
  const PointCloud source = pointsAt({0.005f, -0.005f, 0.005f, -0.005f});
  const DistanceResult r = cloudToCloudDistances(source, {}, target, {}, {});
  ASSERT_EQ(r.matched, 4u);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_NEAR(r.distances[i], i % 2 ? -0.005 : 0.005, 1e-4) << i;
  EXPECT_NEAR(r.mean, 0.005, 1e-4);  // statistics of the magnitudes
  EXPECT_NEAR(r.mean_signed, 0.0, 1e-4);
  // The same floor scanned from below (a ceiling seen from the storey under it): signs swap.
  setOrigins(target, {0, 0, -2.5f});
  const DistanceResult below = cloudToCloudDistances(source, {}, target, {}, {});
  EXPECT_NEAR(below.distances[0], -0.005, 1e-4);
  EXPECT_NEAR(below.distances[1], 0.005, 1e-4);
}

TEST(SignedDistance, WallFarFromTheOriginThroughTransforms) {
  // A wall x = 0 (local), scanned from x = +6 m, in Lambert-93-like coordinates; the target
  // is stored rotated by 90 deg about Z and its transform brings it back.
  const Eigen::Vector3d offset(651234.0, 6862345.0, 40.0);
  PointCloud wall;
  wall.offset = offset;
  for (int i = -30; i <= 30; ++i)
    for (int j = 0; j <= 60; ++j) wall.positions.emplace_back(0.0f, i * 0.05f, j * 0.05f);
  setOrigins(wall, {6.0f, 0.0f, 1.5f});
  const RigidTransform turn(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix(),
                            Eigen::Vector3d::Zero());
  PointCloud stored = wall;
  stored.transform(turn.inverse());
  PointCloud source;
  source.offset = offset;
  source.positions = {{0.005f, 0.5f, 1.0f}, {-0.005f, 0.5f, 1.0f}, {0.02f, -1.0f, 2.0f}};
  const DistanceResult r = cloudToCloudDistances(source, {}, stored, turn, {});
  EXPECT_NEAR(r.distances[0], 0.005, 1e-4);
  EXPECT_NEAR(r.distances[1], -0.005, 1e-4);
  EXPECT_NEAR(r.distances[2], 0.02, 1e-4);
}

TEST(SignedDistance, StoredNormalsAndTheFallbackViewpoint) {
  PointCloud target = floorGrid();
  const PointCloud source = pointsAt({0.005f, -0.005f});
  // No normals, no sensor origins: fitted normals face up.
  const DistanceResult up = cloudToCloudDistances(source, {}, target, {}, {});
  EXPECT_NEAR(up.distances[0], 0.005, 1e-4);
  EXPECT_NEAR(up.distances[1], -0.005, 1e-4);
  // The cloud's own normals (facing down) decide when there are no sensor origins.
  target.normals.assign(target.size(), Eigen::Vector3f(0, 0, -1));
  const DistanceResult down = cloudToCloudDistances(source, {}, target, {}, {});
  EXPECT_NEAR(down.distances[0], -0.005, 1e-4);
  EXPECT_NEAR(down.distances[1], 0.005, 1e-4);
}

TEST(SignedDistance, FarAndNonFinitePointsAreUnmatched) {
  PointCloud target = floorGrid();
  setOrigins(target, {0, 0, 1.6f});
  // Non-finite target points are skipped; their (wrong-side) origins must not be used for the
  // finite ones: the tree's points map back to the right target points.
  for (int k = 0; k < 50; ++k) {
    target.positions.insert(target.positions.begin(), Eigen::Vector3f(kNaN, 0, 0));
    target.sensor_origins.insert(target.sensor_origins.begin(), Eigen::Vector3f(0, 0, -9));
  }
  PointCloud source = pointsAt({-5.0f, 0.005f, -0.005f, 0.0f});
  source.positions[3].x() = kNaN;
  const DistanceResult r = cloudToCloudDistances(source, {}, target, {}, {});
  EXPECT_TRUE(std::isnan(r.distances[0]));  // 5 m below: beyond the 0.1 m radius
  EXPECT_NEAR(r.distances[1], 0.005, 1e-4);
  EXPECT_NEAR(r.distances[2], -0.005, 1e-4);
  EXPECT_TRUE(std::isnan(r.distances[3]));
  EXPECT_EQ(r.matched, 2u);
  DistanceParams wide;
  wide.max_distance = 10.0;
  EXPECT_NEAR(cloudToCloudDistances(source, {}, target, {}, wide).distances[0], -5.0, 1e-4);
  PointCloud nothing;
  nothing.positions.assign(3, Eigen::Vector3f(kNaN, kNaN, kNaN));
  EXPECT_THROW(cloudToCloudDistances(source, {}, nothing, {}, {}), InputError);
}

TEST(SignedDistance, UnsignedOnRequestAndTheParameters) {
  PointCloud target = floorGrid();
  const PointCloud source = pointsAt({0.005f, -0.005f});
  DistanceParams p;
  ASSERT_TRUE(setParam(DistanceParams::schema(), p, "signed", "false"));
  const DistanceResult r = cloudToCloudDistances(source, {}, target, {}, p);
  EXPECT_NEAR(r.distances[0], 0.005, 1e-4);
  EXPECT_NEAR(r.distances[1], 0.005, 1e-4);
  DistanceParams bad;
  bad.normal_neighbours = 2;
  EXPECT_THROW(cloudToCloudDistances(source, {}, target, {}, bad), InputError);
}

TEST(SignedDistance, RepeatedRunsGiveTheSameBits) {
  PointCloud target = floorGrid();
  for (std::size_t i = 0; i < target.size(); ++i)  // a wavy floor: fitted normals vary
    target.positions[i].z() = 0.01f * std::sin(3.0f * target.positions[i].x());
  std::vector<float> heights;
  for (int k = 0; k < 2000; ++k) heights.push_back(0.02f * std::cos(0.7f * float(k)));
  const PointCloud source = pointsAt(heights);
  const DistanceResult a = cloudToCloudDistances(source, {}, target, {}, {});
  const DistanceResult b = cloudToCloudDistances(source, {}, target, {}, {});
  ASSERT_EQ(a.distances.size(), b.distances.size());
  for (std::size_t i = 0; i < a.distances.size(); ++i)
    ASSERT_EQ(std::memcmp(&a.distances[i], &b.distances[i], sizeof(float)), 0) << i;
}

TEST(SignedDistance, CloudToMeshSignFollowsTheTriangleWinding) {
  TriangleMesh mesh;
  mesh.vertices = {{-50, -50, 0}, {50, -50, 0}, {50, 50, 0}, {-50, 50, 0}};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};  // counter-clockwise from above: facing up
  PointCloud source = pointsAt({0.005f, -0.005f, 0.5f, 0.0f});
  source.positions[3].y() = kNaN;
  const DistanceResult r = cloudToMeshDistances(source, {}, mesh, {}, {});
  EXPECT_NEAR(r.distances[0], 0.005, 1e-4);
  EXPECT_NEAR(r.distances[1], -0.005, 1e-4);
  EXPECT_TRUE(std::isnan(r.distances[2]));  // 0.5 m: beyond the radius
  EXPECT_TRUE(std::isnan(r.distances[3]));
  mesh.triangles = {{0, 2, 1}, {0, 3, 2}};  // wound the other way: facing down
  const DistanceResult flipped = cloudToMeshDistances(source, {}, mesh, {}, {});
  EXPECT_NEAR(flipped.distances[0], -0.005, 1e-4);
  EXPECT_NEAR(flipped.distances[1], 0.005, 1e-4);
}

TEST(SignedDistance, DatasetDistancesBecomeTheDistanceField) {
  PointCloud floor = floorGrid();
  setOrigins(floor, {0, 0, 1.6f});
  Dataset d;
  d.scans.resize(2);
  d.scans[0].cloud = pointsAt({0.005f, -0.005f});
  d.scans[1].cloud = pointsAt({0.0f, 0.0f, 0.0f});
  d.scans[1].pose = RigidTransform(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0, 0, -0.01));
  d.scans[1].cloud.scalar_fields.push_back({kDistanceField, Column<float>(3, 7.0f)});  // replaced
  const DatasetDistances dd = datasetDistances(d, {}, DistanceTarget{&floor, nullptr}, {});
  ASSERT_EQ(dd.per_scan.size(), 2u);
  EXPECT_TRUE(dd.signed_values);
  EXPECT_EQ(dd.all.matched, 5u);
  EXPECT_NEAR(dd.per_scan[1][2], -0.01, 1e-4);  // the pose puts scan 2 one centimetre under
  attachDistanceField(d, dd.per_scan);
  for (std::size_t s = 0; s < 2; ++s) {
    const ScalarField* f = d.scans[s].cloud.findScalarField("distance");
    ASSERT_NE(f, nullptr);
    ASSERT_EQ(f->values.size(), dd.per_scan[s].size());
    for (std::size_t i = 0; i < f->values.size(); ++i) EXPECT_EQ(f->values[i], dd.per_scan[s][i]);
  }
  EXPECT_EQ(d.scans[1].cloud.scalar_fields.size(), 1u);
  EXPECT_THROW(attachDistanceField(d, {dd.per_scan[0]}), InputError);
  EXPECT_THROW(datasetDistances(d, {}, DistanceTarget{}, {}), InputError);
}
