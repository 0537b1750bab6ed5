// The real pair room_scan1.pcd / room_scan2.pcd (PCL NDT tutorial, shared/data/README.md:
// real indoor laser scans of one room from two viewpoints, ~112 k points each) registers from
// identity, without the tutorial's initial guess, consistently in both directions, with a
// residual RMS at noise level, and is usable (no warning) both ways; and the transform is the
// right one, checked against two estimates made without Plumb: the tutorial's initial guess
// (robot odometry) and PCL's GICP started from that guess.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <iostream>

#include "io/io.hpp"
#include "room_pair.hpp"
#include "registration/auto/registration_pipeline.hpp"
#include "support/pcl_peers.hpp"
#include "support/test_support.hpp"

using namespace plumb;

namespace {
PointCloud load(const std::string& name) { return test::loadSharedPcd(name); }

/// scan2 -> scan1 as the PCL NDT tutorial starts it ("initial alignment estimate found using
/// robot odometry"): x -> R_z(0.6931 rad) x + (1.79387, 0.720047, 0).
RigidTransform odometryGuess() {
  return RigidTransform(Eigen::AngleAxisd(0.6931, Eigen::Vector3d::UnitZ()).toRotationMatrix(),
                        Eigen::Vector3d(1.79387, 0.720047, 0.0));
}

/// PCL GICP (plane-to-plane, its own normals and covariances: no Plumb code on the way) of
/// `source` onto `target` from `start`.
RigidTransform gicpFrom(const PointCloud& source, const PointCloud& target, const RigidTransform& start) {
  bench::PeerParams p;
  p.voxel = 0.05;             // 5 cm thinning, as Plumb's refinement
  p.icp_max_distance = 0.5;   // odometry is good to decimetres
  p.icp_iterations = 100;
  PointCloud moved = source;
  moved.transform(start);
  const bench::PeerOutcome o = bench::PeerTarget(target, p).run(bench::Peer::Gicp, moved);
  EXPECT_TRUE(o.returned) << "PCL GICP did not converge";
  return o.transform * start;
}

/// Angle (degrees) of the rotation between two transforms.
double rotationBetween(const RigidTransform& x, const RigidTransform& y) {
  return (x * y.inverse()).rotationAngleDeg();
}

using test::rmsDisplacement;
}  // namespace

TEST(RealPair, RoomScansRegisterFromIdentityBothWays) {
  const PointCloud a = load("room_scan1.pcd");
  const PointCloud b = load("room_scan2.pcd");
  ASSERT_EQ(a.size(), 112586u);  // shared/data/README.md
  ASSERT_EQ(b.size(), 112624u);
  PipelineParams p;
  RegistrationSide sa, sb;
  sa.cloud = &a;
  sb.cloud = &b;
  const PipelineResult ba = registerData(sb, sa, p);  // scan2 -> scan1 (tutorial direction)
  for (const auto& l : ba.log) std::cout << l << "\n";
  std::cout << qualityReportToText(ba.report);
  ASSERT_TRUE(ba.success()) << ba.report.verdict;
  const PipelineResult ab = registerData(sa, sb, p);
  for (const auto& l : ab.log) std::cout << l << "\n";
  ASSERT_TRUE(ab.success()) << ab.report.verdict;
  // Right both ways, and nothing to check visually (issue 13: the real pair is usable).
  EXPECT_EQ(ba.report.level, VerdictLevel::Usable) << ba.report.verdict;
  EXPECT_EQ(ab.report.level, VerdictLevel::Usable) << ab.report.verdict;
  const RigidTransform loop = ab.transform() * ba.transform();
  EXPECT_LT(loop.rotationAngleDeg(), 0.1);
  EXPECT_LT(loop.translation().norm(), 0.01);
  // Noise level of this sensor: a few centimetres (robot-mounted scanner).
  EXPECT_LT(ba.report.point_rms, 0.03);
  EXPECT_GT(ba.report.overlap_ratio, 0.3);
}

TEST(RealPair, RoomScansMatchOdometryAndPclGicp) {
  const PointCloud a = load("room_scan1.pcd");
  const PointCloud b = load("room_scan2.pcd");
  RegistrationSide sa, sb;
  sa.cloud = &a;
  sb.cloud = &b;
  const PipelineResult ba = registerData(sb, sa, PipelineParams());  // scan2 -> scan1, from identity
  ASSERT_TRUE(ba.success()) << ba.report.verdict;
  const RigidTransform odometry = odometryGuess();
  const RigidTransform gicp = gicpFrom(b, a, odometry);
  // GICP's minimum does not depend on where it starts: from Plumb's answer it lands on the
  // same transform (measured 0.002 degrees, 0.8 mm).
  const RigidTransform gicp_from_plumb = gicpFrom(b, a, ba.transform());
  EXPECT_LT(rotationBetween(gicp_from_plumb, gicp), 0.05);
  EXPECT_LT(rmsDisplacement(gicp_from_plumb, gicp, b), 0.005);
  const double rot_odo = rotationBetween(ba.transform(), odometry), move_odo = rmsDisplacement(ba.transform(), odometry, b);
  const double rot_gicp = rotationBetween(ba.transform(), gicp), move_gicp = rmsDisplacement(ba.transform(), gicp, b);
  std::cout << "Plumb vs odometry: " << rot_odo << " deg, RMS displacement " << move_odo << " m; vs PCL GICP: "
            << rot_gicp << " deg, " << move_gicp << " m\n";
  // Odometry is only a start (the tutorial runs NDT after it; measured 1.9 degrees and 0.69 m
  // RMS displacement from Plumb's answer). Near it means the right placement: the other
  // placements of this near-rectangular room (turned by 180 degrees, or shifted by a wall's
  // length) move its points by metres.
  EXPECT_LT(rot_odo, 3.0);
  EXPECT_LT(move_odo, 1.0);
  // Two different local optimisers on the same data (Plumb: trimmed point-to-plane ICP on its
  // own grid normals after the plane-based global step; PCL: GICP, plane-to-plane on its own
  // covariances) can differ by the noise they average, not more: measured 0.24 degrees (a
  // tilt about a horizontal axis) and 1.05 cm RMS displacement. Bounds: 0.5 degrees and 2.5
  // cm, below this scanner's noise (point RMS under 3 cm in the test above); a wrong local
  // minimum (a wall matched to its neighbour, a degree of yaw) moves points by decimetres.
  EXPECT_LT(rot_gicp, 0.5);
  EXPECT_LT(move_gicp, 0.025);
}
