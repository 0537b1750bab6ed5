// Trajectory (core/model/trajectory.hpp): interpolation, the trajectory file reader and the
// per-point sensor origins of a timed mobile scan without origins.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <string>

#include "common/error.hpp"
#include "model/trajectory.hpp"
#include "support/test_support.hpp"

namespace plumb {
namespace {

Trajectory lShape() {
  Trajectory t;
  t.times = {10.0, 12.0, 13.0};
  t.positions = {{0, 0, 2}, {4, 0, 2}, {4, 3, 3}};
  return t;
}

/// A scan whose points sit 5 m beside the trajectory at times `times`, stored in a scan frame
/// rotated/shifted by `pose` relative to `offset` (large: like georeferenced data).
Scan timedScan(const Trajectory& t, const std::vector<double>& times, const RigidTransform& pose,
               const Eigen::Vector3d& offset = Eigen::Vector3d(1, 2, 0)) {
  Scan s;
  s.name = "mms";
  s.pose = pose;
  s.has_pose = true;
  s.cloud.offset = offset;
  const RigidTransform to_scan = pose.inverse();
  for (double time : times) {
    const Eigen::Vector3d world = t.position(time) + Eigen::Vector3d(0, 5, 0);
    s.cloud.positions.push_back((to_scan.apply(world) - s.cloud.offset).cast<float>());
    s.cloud.timestamps.push_back(time);
  }
  return s;
}

TEST(Trajectory, InterpolatesAtAndBetweenSamples) {
  const Trajectory t = lShape();
  EXPECT_DOUBLE_EQ(t.duration(), 3.0);
  for (std::size_t i = 0; i < t.times.size(); ++i)
    EXPECT_TRUE(t.position(t.times[i]).isApprox(t.positions[i], 1e-12)) << i;
  EXPECT_TRUE(t.position(10.5).isApprox(Eigen::Vector3d(1, 0, 2), 1e-12));
  EXPECT_TRUE(t.position(12.5).isApprox(Eigen::Vector3d(4, 1.5, 2.5), 1e-12));
  // Clamped at the ends.
  EXPECT_TRUE(t.position(9.0).isApprox(t.positions.front(), 1e-12));
  EXPECT_TRUE(t.position(20.0).isApprox(t.positions.back(), 1e-12));
  // sample() gives the same position and the horizontal heading of the segment.
  Eigen::Vector3d p, h;
  t.sample(12.5, p, h);
  EXPECT_TRUE(p.isApprox(Eigen::Vector3d(4, 1.5, 2.5), 1e-12));
  EXPECT_TRUE(h.isApprox(Eigen::Vector3d::UnitY(), 1e-12));
}

TEST(Trajectory, OriginsOfAPosedScanMapBackToTheTrajectory) {
  const Trajectory t = lShape();
  // Scan frame: rotated about a tilted axis, georeferenced coordinates (near the offset).
  const Eigen::Matrix3d r = Eigen::AngleAxisd(0.7, Eigen::Vector3d(0.2, -0.3, 1).normalized()).toRotationMatrix();
  const Eigen::Vector3d geo(651000.0, 6862000.0, 40.0);
  const RigidTransform pose(r, Eigen::Vector3d(2, 1, 0) - r * geo);
  std::vector<double> times;
  for (int i = 0; i <= 60; ++i) times.push_back(9.5 + i * 0.065);  // 9.5 .. 13.4: both ends clamped
  Dataset d;
  d.source = "mms.las";
  d.scans.push_back(timedScan(t, times, pose, geo));
  d.scans.push_back(timedScan(t, {11.0, 12.25}, RigidTransform()));
  d.scans[1].name = "identity";
  setSensorOriginsFromTrajectory(d, t, "traj.txt");
  for (const Scan& s : d.scans) {
    ASSERT_TRUE(s.cloud.hasSensorOrigins());
    for (std::size_t i = 0; i < s.cloud.size(); ++i) {
      const Eigen::Vector3d world = s.pose.apply(s.cloud.offset + s.cloud.sensor_origins[i].cast<double>());
      const Eigen::Vector3d expected = t.position(s.cloud.timestamps[i]);
      EXPECT_LT((world - expected).norm(), 1e-3) << s.name << " point " << i;
      // And the point is 5 m from its origin, as built.
      EXPECT_NEAR((s.cloud.positions[i] - s.cloud.sensor_origins[i]).norm(), 5.0, 1e-3);
    }
  }
  // Between samples: linear interpolation (12.25 s: a quarter along the second segment).
  const Scan& s = d.scans[1];
  EXPECT_LT((s.cloud.world(1) - s.cloud.offset - s.cloud.sensor_origins[1].cast<double>() -
             Eigen::Vector3d(0, 5, 0)).norm(), 1e-3);
  EXPECT_LT((s.cloud.offset + s.cloud.sensor_origins[1].cast<double>() - Eigen::Vector3d(4, 0.75, 2.25)).norm(),
            1e-3);
}

TEST(Trajectory, ScanWithoutTimestampsIsAnErrorNamingTheDataset) {
  const Trajectory t = lShape();
  Dataset d;
  d.source = "outdoor.e57";
  d.scans.push_back(timedScan(t, {10.0, 11.0}, RigidTransform()));
  d.scans.push_back(timedScan(t, {10.0, 11.0}, RigidTransform()));
  d.scans[1].name = "second";
  d.scans[1].cloud.timestamps.clear();
  try {
    setSensorOriginsFromTrajectory(d, t, "traj.txt");
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("outdoor.e57"), std::string::npos) << m;
    EXPECT_NE(m.find("'second'"), std::string::npos) << m;
    EXPECT_NE(m.find("timestamps"), std::string::npos) << m;
  }
  // Nothing changed, not even the first (valid) scan.
  EXPECT_FALSE(d.scans[0].cloud.hasSensorOrigins());
}

TEST(Trajectory, TimesOutsideTheTrajectoryAreCountedInTheError) {
  const Trajectory t = lShape();  // 10 .. 13 s
  Dataset d;
  d.source = "outdoor.las";
  // 7 points inside or within 1 s of the ends, 3 beyond (8.5, 14.5, 400000).
  d.scans.push_back(timedScan(t, {9.2, 10, 11, 12, 13, 13.9, 8.5, 14.5, 12.5, 400000.0}, RigidTransform()));
  try {
    setSensorOriginsFromTrajectory(d, t, "traj.txt");
    FAIL() << "no error";
  } catch (const FileError& e) {
    const std::string m = e.what();
    EXPECT_EQ(e.file(), "traj.txt");
    EXPECT_NE(m.find("3 of 10 points"), std::string::npos) << m;
    EXPECT_NE(m.find("outdoor.las"), std::string::npos) << m;
    EXPECT_NE(m.find("[8.500, 400000.000] s"), std::string::npos) << m;  // the points' range
    EXPECT_NE(m.find("[10.000, 13.000] s"), std::string::npos) << m;     // the trajectory's
  }
  EXPECT_FALSE(d.scans[0].cloud.hasSensorOrigins());
  // Within the tolerance only: accepted, clamped to the end positions.
  d.scans[0] = timedScan(t, {9.2, 13.9}, RigidTransform());
  setSensorOriginsFromTrajectory(d, t, "traj.txt");
  EXPECT_LT((d.scans[0].cloud.offset + d.scans[0].cloud.sensor_origins[0].cast<double>() - t.positions.front()).norm(), 1e-3);
  EXPECT_LT((d.scans[0].cloud.offset + d.scans[0].cloud.sensor_origins[1].cast<double>() - t.positions.back()).norm(), 1e-3);
}

TEST(Trajectory, ReadsFilesAndNamesTheBadLine) {
  const auto dir = test::scratchDir("model-trajectory");
  test::writeAll(dir / "ok.txt", "# t x y z\n\n100.5 1 2 3   # first\n101.5,4,5,6\n");
  const Trajectory t = readTrajectory(dir / "ok.txt");
  ASSERT_EQ(t.times.size(), 2u);
  EXPECT_DOUBLE_EQ(t.times[0], 100.5);
  EXPECT_TRUE(t.positions[1].isApprox(Eigen::Vector3d(4, 5, 6)));

  struct Case {
    std::string text;
    std::uint64_t line;
    std::string what;
  };
  for (const Case& c : {Case{"0 0 0 0\n1 0 0\n", 2, "expected 4 numbers"},
                        Case{"0 0 0 0\n1 0 0 0\n# c\n1 1 1 1\n", 4, "increase strictly"},
                        Case{"0 0 0 0\n1 0 0 0 7\n", 2, "expected 4 numbers"},
                        Case{"0 0 0 0\n1 x 0 0\n", 2, "expected 4 numbers"}}) {
    test::writeAll(dir / "bad.txt", c.text);
    try {
      readTrajectory(dir / "bad.txt");
      ADD_FAILURE() << "no error for " << c.text;
    } catch (const FileError& e) {
      const std::string m = e.what();
      EXPECT_EQ(e.where().line.value_or(0), c.line) << m;
      EXPECT_NE(m.find("bad.txt"), std::string::npos) << m;
      EXPECT_NE(m.find("line " + std::to_string(c.line)), std::string::npos) << m;
      EXPECT_NE(m.find(c.what), std::string::npos) << m;
    }
  }
  test::writeAll(dir / "one.txt", "0 0 0 0\n");
  EXPECT_THROW(readTrajectory(dir / "one.txt"), FileError);
  EXPECT_THROW(readTrajectory(dir / "missing.txt"), FileError);
}

}  // namespace
}  // namespace plumb
