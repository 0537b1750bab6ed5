#include <gtest/gtest.h>

#include <filesystem>

#include "common/error.hpp"
#include "model/rigid_transform.hpp"
#include "support/test_support.hpp"

using namespace plumb;

namespace {
RigidTransform sample() {
  const Eigen::Matrix3d r =
      (Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(-0.2, Eigen::Vector3d::UnitX()))
          .toRotationMatrix();
  return RigidTransform(r, Eigen::Vector3d(651234.125, 6862123.5, 42.25));
}
}  // namespace

TEST(RigidTransform, ComposeAndInverse) {
  const RigidTransform a = sample();
  const RigidTransform b = RigidTransform::fromYaw(1.0, {1, 2, 3});
  const Eigen::Vector3d p(3, -4, 5);
  EXPECT_TRUE((a * b).apply(p).isApprox(a.apply(b.apply(p)), 1e-12));
  EXPECT_TRUE((a * a.inverse()).isIdentity(1e-9));
  EXPECT_NEAR(RigidTransform::fromYaw(M_PI / 2, {}).rotationAngleDeg(), 90.0, 1e-9);
  EXPECT_NEAR(RigidTransform::rotationErrorDeg(a, b * a), 57.29577951308232, 1e-6);
}

TEST(RigidTransform, JsonAndTextRoundTripKeepMillimetres) {
  const RigidTransform a = sample();
  const RigidTransform j = transformFromJson(transformToJson(a));
  const RigidTransform t = transformFromText(transformToText(a));
  EXPECT_LT(RigidTransform::translationError(a, j), 1e-9);
  EXPECT_LT(RigidTransform::rotationErrorDeg(a, j), 1e-9);
  EXPECT_LT(RigidTransform::translationError(a, t), 1e-9);
  EXPECT_NE(transformToJson(a).find("\"matrix\""), std::string::npos);
}

TEST(RigidTransform, FilesByExtension) {
  const auto dir = test::scratchDir("rigid_transform_files");
  const RigidTransform a = sample();
  writeTransformFile(dir / "t.json", a);
  writeTransformFile(dir / "t.txt", a);
  EXPECT_EQ(test::readAll(dir / "t.json").front(), '{');
  EXPECT_LT(RigidTransform::translationError(readTransformFile(dir / "t.json"), a), 1e-9);
  EXPECT_LT(RigidTransform::translationError(readTransformFile(dir / "t.txt"), a), 1e-9);
}

TEST(RigidTransform, RejectsBadInputWithLocation) {
  const auto dir = test::scratchDir("rigid_transform_bad");
  test::writeAll(dir / "scale.txt", "2 0 0 0\n0 2 0 0\n0 0 2 0\n0 0 0 1\n");
  EXPECT_THROW(readTransformFile(dir / "scale.txt"), FileError);
  test::writeAll(dir / "short.txt", "1 0 0 0\n0 1 0\n");
  try {
    readTransformFile(dir / "short.txt");
    FAIL() << "expected FileError";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("short.txt"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("line 2"), std::string::npos);
  }
  test::writeAll(dir / "bad.json", "{\"matrix\": [[1,0,0,0],[0,1,0,0],[0,0,1,\"x\"],[0,0,0,1]]}");
  try {
    readTransformFile(dir / "bad.json");
    FAIL() << "expected FileError";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("matrix[2][3]"), std::string::npos);
  }
  test::writeAll(dir / "empty.json", "");
  EXPECT_THROW(readTransformFile(dir / "empty.json"), FileError);
}
