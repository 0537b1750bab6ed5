#include <gtest/gtest.h>

#include "common/error.hpp"
#include "model/bim_model.hpp"
#include "model/dataset.hpp"
#include "model/point_cloud.hpp"

using namespace plumb;

namespace {
PointCloud georeferenced() {
  PointCloud c;
  c.offset = {651000.0, 6862000.0, 40.0};  // Lambert-93 sized coordinates
  c.positions = {{0.001f, 0.002f, 0.003f}, {12.345f, -6.789f, 3.0f}, {100.0f, 200.0f, 10.0f}};
  c.intensity = {1.f, 2.f, 3.f};
  c.normals = {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}};
  return c;
}
}  // namespace

TEST(PointCloud, GeoreferencedPositionsKeepMillimetres) {
  PointCloud c = georeferenced();
  EXPECT_NEAR(c.world(0).x(), 651000.001, 1e-6);
  const Bounds b = c.bounds();
  EXPECT_NEAR(b.max.y(), 6862200.0, 1e-6);
  // A translation of 1 mm in world coordinates survives exactly at this magnitude.
  c.transform(RigidTransform(Eigen::Matrix3d::Identity(), {0.001, 0, 0}));
  EXPECT_NEAR(c.world(0).x(), 651000.002, 1e-6);
}

TEST(PointCloud, RotationAboutWorldOriginAppliesToOffsetFrame) {
  PointCloud c = georeferenced();
  const RigidTransform t = RigidTransform::fromYaw(M_PI / 2, {0, 0, 0});
  const Eigen::Vector3d expected = t.apply(c.world(1));
  c.transform(t);
  // float positions relative to an unchanged offset: error bounded by float spacing at ~7e6.
  EXPECT_NEAR((c.world(1) - expected).norm(), 0.0, 1.0);
  EXPECT_TRUE(c.normals[1].isApprox(Eigen::Vector3f(0, 1, 0), 1e-6f));
}

TEST(PointCloud, FilterSubsetAppendKeepAttributesAligned) {
  PointCloud c = georeferenced();
  c.filter({true, false, true});
  ASSERT_EQ(c.size(), 2u);
  EXPECT_FLOAT_EQ(c.intensity[1], 3.f);
  PointCloud s = c.subset({1});
  ASSERT_EQ(s.size(), 1u);
  EXPECT_FLOAT_EQ(s.intensity[0], 3.f);
  PointCloud other;
  other.offset = c.offset + Eigen::Vector3d(1, 0, 0);
  other.positions = {{0, 0, 0}};
  other.intensity = {9.f};
  const Eigen::Vector3d w = other.world(0);
  c.append(other);
  ASSERT_EQ(c.size(), 3u);
  EXPECT_TRUE(c.hasIntensity());
  EXPECT_FALSE(c.hasNormals());  // only one side had normals
  EXPECT_NEAR((c.world(2) - w).norm(), 0.0, 1e-6);
}

TEST(PointCloud, ValidateRejectsMisalignedAttributes) {
  PointCloud c = georeferenced();
  c.intensity.pop_back();
  EXPECT_THROW(c.validate(), InputError);
  EXPECT_EQ(c.fieldNames().size(), 6u);  // x y z nx ny nz; intensity no longer complete
}

TEST(Dataset, MergedAppliesScanPosesAndTagsScans) {
  Dataset d;
  for (int k = 0; k < 2; ++k) {
    Scan s;
    s.name = "s" + std::to_string(k);
    s.pose = RigidTransform::fromYaw(k * M_PI / 2, {10.0 * k, 0, 0});
    s.cloud.positions = {{1, 0, 0}};
    d.scans.push_back(s);
  }
  PointCloud m = d.merged(true);
  ASSERT_EQ(m.size(), 2u);
  EXPECT_NEAR((m.world(1) - Eigen::Vector3d(10, 1, 0)).norm(), 0, 1e-6);
  EXPECT_EQ(m.scan_id[1], 1);
  ASSERT_TRUE(m.hasSensorOrigins());
  EXPECT_NEAR((m.sensor_origins[1].cast<double>() + m.offset - Eigen::Vector3d(10, 0, 0)).norm(), 0, 1e-6);
  EXPECT_EQ(d.pointCount(), 2u);
}

TEST(BimModel, AreaBoundsAndElementTypes) {
  BimModel m;
  m.mesh.vertices = {{0, 0, 0}, {2, 0, 0}, {0, 3, 0}, {0, 0, 4}};
  m.mesh.triangles = {{0, 1, 2}, {0, 1, 3}};
  m.elements = {{"IfcSlab", "floor", ""}, {"IfcWall", "w", ""}};
  m.triangle_element = {0, 1};
  EXPECT_DOUBLE_EQ(m.mesh.area(), 3.0 + 4.0);
  EXPECT_DOUBLE_EQ(m.mesh.bounds().max.z(), 4.0);
  EXPECT_EQ(m.trianglesOfType("IfcWall"), std::vector<std::uint32_t>{1});
  EXPECT_TRUE(m.mesh.triangleNormal(0).isApprox(Eigen::Vector3d(0, 0, 1)));
}
