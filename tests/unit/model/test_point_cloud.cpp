#include <gtest/gtest.h>

#include "common/error.hpp"
#include "model/bim_model.hpp"
#include "model/dataset.hpp"
#include "model/point_cloud.hpp"

using namespace plumb;

namespace {
// The README's precision claim ("coordinates survive ... to 0.1 mm"); tests hold to it.
constexpr double kClaim = 1e-4;
static_assert(kClaim == kCoordinatePrecision, "README claim and core constant differ");

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
  // The offset is rotated in double; the local coordinates only rotate: no float rounding at ~7e6.
  EXPECT_NEAR((c.world(1) - expected).norm(), 0.0, kClaim);
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

namespace {
/// A cloud whose exact world coordinates are `truth` (offset chosen like a reader, residuals
/// kept), with intensity i for point i.
PointCloud cloudAt(const std::vector<Eigen::Vector3d>& truth) {
  PointCloud c;
  c.offset = offsetFromSample(truth);
  c.positions.resize(truth.size());
  c.position_residuals.resize(truth.size());
  for (std::size_t i = 0; i < truth.size(); ++i) {
    c.setLocal(i, truth[i] - c.offset);
    c.intensity.push_back(static_cast<float>(i));
  }
  c.dropNegligibleResiduals();
  return c;
}

/// Points spread over `span` metres around `centre`, with sub-millimetre decimals.
std::vector<Eigen::Vector3d> spread(const Eigen::Vector3d& centre, double span, int n) {
  std::vector<Eigen::Vector3d> v;
  for (int i = 0; i < n; ++i) {
    const double f = n > 1 ? static_cast<double>(i) / (n - 1) - 0.5 : 0.0;
    v.push_back(centre + Eigen::Vector3d(f * span + 0.12345 * i, -f * span + 0.06789 * i, 0.0371 * i));
  }
  return v;
}

double maxError(const PointCloud& c, const std::vector<Eigen::Vector3d>& truth) {
  double e = 0;
  for (std::size_t i = 0; i < truth.size(); ++i) e = std::max(e, (c.world(i) - truth[i]).cwiseAbs().maxCoeff());
  return e;
}
}  // namespace

TEST(PointCloudPrecision, LargeTranslationTransformKeepsSubMillimetre) {
  // Small local coordinates moved into Lambert-93 by a pose with a rotation (what register -o,
  // convert --transform and merging do): float32 at 6.86e6 has a 0.5 m step.
  PointCloud c;
  c.positions = {{1.2345f, -7.891f, 2.5f}, {-30.125f, 12.0625f, 0.75f}, {250.5f, 125.25f, 3.0f}};
  std::vector<Eigen::Vector3d> before;
  for (std::size_t i = 0; i < c.size(); ++i) before.push_back(c.world(i));
  const RigidTransform t = RigidTransform::fromYaw(0.3, {651000.1234, 6860000.5678, 40.25});
  c.transform(t);
  for (std::size_t i = 0; i < c.size(); ++i) EXPECT_LT((c.world(i) - t.apply(before[i])).norm(), kClaim) << i;
  // And back: the inverse restores the original coordinates.
  c.transform(t.inverse());
  for (std::size_t i = 0; i < c.size(); ++i) EXPECT_LT((c.world(i) - before[i]).norm(), kClaim) << i;
}

TEST(PointCloudPrecision, PureTranslationMovesOnlyTheOffset) {
  PointCloud c = georeferenced();
  const auto positions = c.positions;
  c.transform(RigidTransform(Eigen::Matrix3d::Identity(), {123456.789, -0.001, 9123456.5}));
  EXPECT_EQ(c.positions, positions);
  EXPECT_FALSE(c.hasPositionResiduals());
  EXPECT_NEAR(c.offset.x(), 651000.0 + 123456.789, 1e-9);
}

TEST(PointCloudPrecision, SixtyKilometreCloudKeepsResidualsThroughEdits) {
  // 60 km wide: float positions around one offset have a ~2 mm step at 30 km from it.
  const auto truth = spread({651000.0, 6860000.0, 40.0}, 60000.0, 101);
  PointCloud c = cloudAt(truth);
  ASSERT_TRUE(c.hasPositionResiduals());
  EXPECT_LT(maxError(c, truth), 1e-6);
  for (const auto& name : c.fieldNames()) EXPECT_NE(name, "position_residuals");
  EXPECT_GE(c.memoryBytes(), 101u * (12 + 12 + 4));
  // setOffset, subset, filter and a rotation there and back keep every coordinate.
  c.setOffset({600000.5, 6800000.25, 0.0});
  EXPECT_LT(maxError(c, truth), 1e-6);
  const RigidTransform t = RigidTransform::fromYaw(1.1, {-5000.0, 2500.0, 1.0});
  c.transform(t);
  c.transform(t.inverse());
  EXPECT_LT(maxError(c, truth), 1e-6);
  const PointCloud s = c.subset({100, 0});
  EXPECT_LT((s.world(0) - truth[100]).norm(), 1e-6);
  EXPECT_LT((s.world(1) - truth[0]).norm(), 1e-6);
  std::vector<bool> keep(truth.size(), false);
  keep[50] = keep[99] = true;
  c.filter(keep);
  ASSERT_EQ(c.size(), 2u);
  EXPECT_LT((c.world(1) - truth[99]).norm(), 1e-6);
  c.validate(true);
}

TEST(PointCloudPrecision, AppendReexpressesExactCoordinates) {
  const auto a = spread({651000.0, 6860000.0, 40.0}, 20000.0, 21);
  const auto b = spread({9123456.789, 512345.678, 12.0}, 30000.0, 31);  // UTM northing > 2^23
  PointCloud c = cloudAt(a);
  c.append(cloudAt(b));
  ASSERT_EQ(c.size(), 52u);
  EXPECT_TRUE(c.hasIntensity());
  std::vector<Eigen::Vector3d> all = a;
  all.insert(all.end(), b.begin(), b.end());
  EXPECT_LT(maxError(c, all), 1e-6);
}

TEST(PointCloudPrecision, NegligibleResidualsAreDropped) {
  PointCloud c = cloudAt({{1.5, 2.25, 3.0}, {100.0, 200.0, 0.5}});
  EXPECT_FALSE(c.hasPositionResiduals());
  EXPECT_EQ(c.offset, Eigen::Vector3d::Zero());  // small clouds keep offset zero
}

TEST(PointCloudPrecision, OffsetFromSampleIgnoresOddFirstPoints) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<Eigen::Vector3d> s = {{nan, nan, nan}, {0, 0, 0}, {5000000.1234, 651000.4, 40.6},
                                    {5000001.9, 651002.2, 41.2}, {5000003.0, 651001.0, 39.9}};
  EXPECT_EQ(offsetFromSample(s), Eigen::Vector3d(5000002.0, 651001.0, 41.0));
  EXPECT_EQ(offsetFromSample({{nan, 0, 0}, {12.5, 9999.0, -3.0}}), Eigen::Vector3d::Zero());
}

TEST(Dataset, MergedScansWithGridPosesKeepSubMillimetre) {
  // Two stations posed in Lambert-93 with rotations: the merged cloud in the dataset frame.
  Dataset d;
  std::vector<Eigen::Vector3d> truth;
  for (int k = 0; k < 2; ++k) {
    Scan s;
    s.pose = RigidTransform::fromYaw(0.4 + k, {651000.1234 + 20.0 * k, 6860000.5678 - 5.0 * k, 40.25});
    s.cloud.positions = {{1.2345f, -7.891f, 2.5f}, {-30.125f, 12.0625f, 0.75f}};
    for (const auto& p : s.cloud.positions) truth.push_back(s.pose.apply(p.cast<double>()));
    d.scans.push_back(s);
  }
  const PointCloud m = d.merged();
  ASSERT_EQ(m.size(), truth.size());
  EXPECT_LT(maxError(m, truth), kClaim);
  EXPECT_LT((d.bounds().min - m.bounds().min).norm(), 0.01);
}

TEST(Dataset, TransformMovesEveryScanPoseExactly) {
  // A registration result applied to a two-station dataset in Lambert-93: poses composed in
  // double, points untouched, a scan without a pose gets one.
  Dataset d;
  d.scans.resize(2);
  d.scans[0].pose = RigidTransform::fromYaw(0.4, {651000.1234, 6860000.5678, 40.25});
  d.scans[0].has_pose = true;
  d.scans[1].cloud.positions = {{1.5f, -2.25f, 0.5f}};
  const RigidTransform T = RigidTransform::fromYaw(-1.1, {12.0625, -3.5, 0.125});
  const Dataset before = d;
  d.transform(T);
  for (std::size_t i = 0; i < 2; ++i) {
    const RigidTransform expected = T * before.scans[i].pose;
    EXPECT_TRUE(d.scans[i].has_pose);
    EXPECT_LT((d.scans[i].pose.translation() - expected.translation()).norm(), 1e-9);
    EXPECT_LT(RigidTransform::rotationErrorDeg(d.scans[i].pose, expected), 1e-9);
    EXPECT_EQ(d.scans[i].cloud.positions, before.scans[i].cloud.positions);
  }
}

TEST(PointCloud, AppendKeepsLasFieldsPresentOnOneSideOnly) {
  // The LAS reader leaves an all-zero field out, so a merge of a scan that has point source
  // IDs with one that has none must keep them (0 for the other scan), not drop the column.
  PointCloud a, b;
  a.positions.assign(2, Eigen::Vector3f::Zero());
  b.positions.assign(3, Eigen::Vector3f::Ones());
  a.point_source_id = {7, 8};
  b.scan_angle.assign(3, 12.5f);
  a.append(b);
  ASSERT_EQ(a.point_source_id.size(), 5u);
  EXPECT_EQ(a.point_source_id[1], 8);
  EXPECT_EQ(a.point_source_id[4], 0);
  ASSERT_EQ(a.scan_angle.size(), 5u);
  EXPECT_EQ(a.scan_angle[0], 0.0f);
  EXPECT_EQ(a.scan_angle[2], 12.5f);
  EXPECT_TRUE(a.user_data.empty());  // neither side has it
}

TEST(PointCloudPrecision, BoundsContainEveryExactCoordinate) {
  // 30 km from the offset a float steps by 2 mm: bounds from the floats alone could miss the
  // exact extreme by up to 1 mm, and a quantizing writer (E57) would store a value outside them.
  PointCloud c;
  c.offset = {651000.0, 6860000.0, 40.0};
  c.positions.resize(2);
  c.position_residuals.resize(2);
  PointCloud::splitLocal({30000.0007, -30000.0009, 0.0003}, c.positions[0], c.position_residuals[0]);
  PointCloud::splitLocal({-29999.9993, 29999.9991, 0.0}, c.positions[1], c.position_residuals[1]);
  const Bounds b = c.bounds();
  for (std::size_t i = 0; i < 2; ++i)
    for (int a = 0; a < 3; ++a) {
      EXPECT_LE(b.min[a], c.world(i)[a]);
      EXPECT_GE(b.max[a], c.world(i)[a]);
    }
  EXPECT_DOUBLE_EQ(b.max.x(), 651000.0 + 30000.0007);
}
