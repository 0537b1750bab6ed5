// Registration from any 3D orientation (issue 14). The real pair room_scan2 -> room_scan1
// (shared/data/README.md) registers from identity (levelled, yaw only); room_scan2 tilted by
// 15, 45 and 90 degrees about X and about Y, and turned Y-up, must register to the same
// result: the transform found for the tilted scan, composed with the tilt, equals the one
// found from identity within 0.05 degree and 5 mm (RMS displacement of the scan's points).
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <iostream>

#include "room_pair.hpp"
#include "registration/auto/registration_pipeline.hpp"

using namespace plumb;

namespace {

PointCloud load(const std::string& name) { return test::loadSharedPcd(name); }

struct RoomPair {
  PointCloud target = load("room_scan1.pcd");
  PointCloud source = load("room_scan2.pcd");
  FeatureSet target_features;
  RigidTransform from_identity;
  RoomPair() {
    RegistrationSide s, t;
    s.cloud = &source;
    t.cloud = &target;
    const PipelineResult r = registerData(s, t, PipelineParams());
    EXPECT_EQ(r.report.level, VerdictLevel::Usable) << r.report.verdict;
    from_identity = r.transform();
    target_features = r.target_features;
  }
};

const RoomPair& pair() {
  static const RoomPair p;
  return p;
}

using test::rmsDisplacement;

/// Registers room_scan2 moved by `tilt` and compares (found * tilt) with the identity result.
void expectSameAsFromIdentity(const RigidTransform& tilt, SourceOrientation orientation) {
  const RoomPair& rp = pair();
  PointCloud moved = rp.source;
  moved.transform(tilt);
  RegistrationSide s, t;
  s.cloud = &moved;
  t.cloud = &rp.target;
  t.features = &rp.target_features;
  PipelineParams p;
  p.orientation.source = orientation;
  const PipelineResult r = registerData(s, t, p);
  for (const auto& l : r.log)
    if (l.rfind("orientation", 0) == 0) std::cout << l << "\n";
  std::cout << r.report.verdict << "\n";
  ASSERT_EQ(r.report.level, VerdictLevel::Usable) << r.report.verdict;
  const RigidTransform found = r.transform() * tilt;
  const double rot = (found * rp.from_identity.inverse()).rotationAngleDeg();
  const double move = rmsDisplacement(found, rp.from_identity, rp.source);
  std::cout << "vs from identity: " << rot << " deg, " << move * 1000 << " mm RMS displacement\n";
  EXPECT_LT(rot, 0.05);
  EXPECT_LT(move, 0.005);
}

RigidTransform about(const Eigen::Vector3d& axis, double deg) {
  return RigidTransform(Eigen::AngleAxisd(deg * M_PI / 180.0, axis).toRotationMatrix(),
                        Eigen::Vector3d::Zero());
}

}  // namespace

// Each test one process (CTest runs them in parallel); the identity result is computed once
// per process.
TEST(TiltedSource, AboutX) {
  for (double deg : {15.0, 45.0, 90.0}) {
    SCOPED_TRACE(deg);
    expectSameAsFromIdentity(about(Eigen::Vector3d::UnitX(), deg), SourceOrientation::Auto);
  }
}

TEST(TiltedSource, AboutY) {
  for (double deg : {15.0, 45.0, 90.0}) {
    SCOPED_TRACE(deg);
    expectSameAsFromIdentity(about(Eigen::Vector3d::UnitY(), deg), SourceOrientation::Auto);
  }
}

// Y-up data (+Z of the room turned onto +Y: a quarter turn of -90 degrees about X), found by
// auto and declared with orientation.source = y-up.
TEST(TiltedSource, YUpFoundByAutoAndDeclared) {
  const RigidTransform y_up = about(Eigen::Vector3d::UnitX(), -90);
  expectSameAsFromIdentity(y_up, SourceOrientation::Auto);
  expectSameAsFromIdentity(y_up, SourceOrientation::YUp);
}

// Any: every up direction tried, the levelled one among them.
TEST(TiltedSource, LevelledWithOrientationAny) {
  expectSameAsFromIdentity(RigidTransform(), SourceOrientation::Any);
}

// A tilted scan and orientation "levelled" (the old behaviour): no answer, never a wrong one.
TEST(TiltedSource, TiltedButDeclaredLevelledFails) {
  const RoomPair& rp = pair();
  PointCloud moved = rp.source;
  moved.transform(about(Eigen::Vector3d::UnitX(), 45));
  RegistrationSide s, t;
  s.cloud = &moved;
  t.cloud = &rp.target;
  t.features = &rp.target_features;
  PipelineParams p;
  p.orientation.source = SourceOrientation::Levelled;
  const PipelineResult r = registerData(s, t, p);
  EXPECT_NE(r.report.level, VerdictLevel::Usable) << r.report.verdict;
}
