// The point-to-plane ICP step alone (registration/refine/point_to_plane.hpp): factor (Jacobian),
// reduction (normal equations), optimizer (step, convergence), trimming, stage distances and
// the inlier figures the quality report reads.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <random>

#include "registration/refine/point_to_plane.hpp"

using namespace plumb::refine_detail;

namespace {

/// Correspondences of points on the three planes x = 0, y = 0, z = 0 (normals the axes) after
/// the small motion x -> dR x + dt: the target point q is p's foot on the plane before the
/// motion, so the residual r = n·(p - q) is exactly the motion's normal component.
std::vector<PlaneCorrespondence> movedCorner(const Eigen::Matrix3d& dR, const Eigen::Vector3d& dt) {
  std::vector<PlaneCorrespondence> c;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.2, 2.0);
  for (int axis = 0; axis < 3; ++axis)
    for (int k = 0; k < 40; ++k) {
      Eigen::Vector3d y(u(rng), u(rng), u(rng));
      y[axis] = 0;
      const Eigen::Vector3d n = Eigen::Vector3d::Unit(axis);
      const Eigen::Vector3d p = dR * y + dt;
      c.push_back({p, y, n, n.dot(p - y)});
    }
  return c;
}

}  // namespace

TEST(PointToPlane, JacobianIsTheDerivativeOfTheResidual) {
  const PlaneCorrespondence c{{1.0, 2.0, 0.5}, {1.0, 2.0, 0.0}, Eigen::Vector3d(0.0, 0.6, 0.8), 0.0};
  const Vector6d j = pointToPlaneJacobian(c);
  // r(xi) = n·(p + w x p + dt - q): finite differences along each of the six coordinates.
  const double h = 1e-7;
  for (int k = 0; k < 6; ++k) {
    Vector6d xi = Vector6d::Zero();
    xi[k] = h;
    const Eigen::Vector3d moved = c.p + xi.head<3>().cross(c.p) + xi.tail<3>();
    EXPECT_NEAR((c.n.dot(moved - c.q) - c.n.dot(c.p - c.q)) / h, j[k], 1e-6) << k;
  }
}

TEST(PointToPlane, OneStepUndoesASmallMotionOfACorner) {
  const Eigen::Matrix3d dR = Eigen::AngleAxisd(0.01, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Eigen::Vector3d dt(0.02, -0.01, 0.015);
  const auto c = movedCorner(dR, dt);
  const NormalEquations eq = accumulateNormalEquations(c);
  EXPECT_NEAR((eq.H - eq.H.transpose()).norm(), 0.0, 1e-12);
  const IcpStep s = solveIcpStep(eq);
  ASSERT_TRUE(s.finite);
  // The step applied after the motion brings the points back (to first order in the angle).
  const Eigen::Matrix3d R = s.dR * dR;
  const Eigen::Vector3d t = s.dR * dt + s.dt;
  EXPECT_LT(Eigen::AngleAxisd(R).angle(), 1e-3);  // of a 0.01 rad motion
  EXPECT_LT(t.norm(), 5e-3);                       // of a 27 mm motion
  EXPECT_NEAR(s.angle, 0.01, 1e-3);
  EXPECT_FALSE(stepConverged(s));
}

TEST(PointToPlane, ZeroResidualsGiveAConvergedZeroStepAndANonFiniteSystemNone) {
  auto c = movedCorner(Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero());
  const IcpStep still = solveIcpStep(accumulateNormalEquations(c));
  ASSERT_TRUE(still.finite);
  EXPECT_EQ(still.angle, 0.0);
  EXPECT_TRUE(stepConverged(still));
  NormalEquations broken = accumulateNormalEquations(c);
  broken.g[0] = std::nan("");  // a NaN residual: no usable step
  EXPECT_FALSE(solveIcpStep(broken).finite);
}

TEST(PointToPlane, TrimmingKeepsTheSmallestResiduals) {
  std::vector<PlaneCorrespondence> c;
  for (int k = 0; k < 20; ++k) c.push_back({Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), (k % 2 ? -1.0 : 1.0) * k});
  trimCorrespondences(c, 0.5, false);
  ASSERT_EQ(c.size(), 10u);
  for (const auto& k : c) EXPECT_LT(std::abs(k.r), 10.0);
  trimCorrespondences(c, 0.5, false);  // 10 left: trimmed to max(6, 5)
  EXPECT_EQ(c.size(), 6u);
  trimCorrespondences(c, 0.5, false);  // fewer than 10: untouched
  EXPECT_EQ(c.size(), 6u);
}

TEST(PointToPlane, TrimmingPerDirectionKeepsEveryWallDirection) {
  // 80 floor correspondences fitting well and 20 on one wall 5 cm off (a start displaced
  // along the wall's normal): a global 90% trim drops half the wall, a per-direction trim
  // keeps 90% of each.
  std::vector<PlaneCorrespondence> c;
  for (int k = 0; k < 80; ++k)
    c.push_back({Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), 0.001 * (k % 5)});
  for (int k = 0; k < 20; ++k)
    c.push_back({Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitY(), 0.05 + 0.001 * k});
  const auto walls = [](const std::vector<PlaneCorrespondence>& v) {
    return std::count_if(v.begin(), v.end(), [](const PlaneCorrespondence& k) { return k.n.y() > 0.5; });
  };
  auto global = c;
  trimCorrespondences(global, 0.9, false);
  EXPECT_EQ(global.size(), 90u);
  EXPECT_EQ(walls(global), 10);
  trimCorrespondences(c, 0.9, true);
  EXPECT_EQ(c.size(), 90u);
  EXPECT_EQ(walls(c), 18);
  for (const auto& k : c)
    if (k.n.y() > 0.5) EXPECT_LT(k.r, 0.068);  // the wall's own largest two are the ones dropped
}

TEST(PointToPlane, StageDistancesShrinkGeometricallyFromStartToFinal) {
  EXPECT_DOUBLE_EQ(stageDistance(0.5, 0.05, 4, 0), 0.5);
  EXPECT_NEAR(stageDistance(0.5, 0.05, 4, 3), 0.05, 1e-15);
  EXPECT_NEAR(stageDistance(0.5, 0.05, 4, 1) / stageDistance(0.5, 0.05, 4, 0),
              stageDistance(0.5, 0.05, 4, 2) / stageDistance(0.5, 0.05, 4, 1), 1e-12);
  EXPECT_DOUBLE_EQ(stageDistance(0.5, 0.05, 1, 0), 0.5);  // one stage: the start distance
}

TEST(PointToPlane, InlierFiguresCountOnlyResidualsWithinTheDistance) {
  const Eigen::Vector3d o = Eigen::Vector3d::Zero(), z = Eigen::Vector3d::UnitZ();
  std::vector<PlaneCorrespondence> c{{{1, 0, 0}, o, z, 0.03}, {{-1, 0, 0}, o, z, -0.04}, {{5, 5, 5}, o, z, 0.2}};
  const InlierFigures f = inlierFigures(c, 0.05);
  EXPECT_EQ(c.size(), 2u);
  EXPECT_EQ(f.inliers, 2u);
  EXPECT_NEAR(f.rms, std::sqrt((0.03 * 0.03 + 0.04 * 0.04) / 2), 1e-15);
  EXPECT_NEAR(f.centre.norm(), 0.0, 1e-15);
  EXPECT_NEAR(f.length_scale, 1.0, 1e-15);
  // Two points on the x axis with normal z: they hold z and the rotation about y only.
  EXPECT_NEAR(f.normal_matrix(5, 5), 2.0, 1e-12);  // dt_z
  EXPECT_NEAR(f.normal_matrix(1, 1), 2.0, 1e-12);  // w_y: (p x n)_y = -x
  EXPECT_EQ(f.normal_matrix(3, 3), 0.0);           // dt_x free
  std::vector<PlaneCorrespondence> none{{o, o, z, 1.0}};
  const InlierFigures g = inlierFigures(none, 0.05);
  EXPECT_EQ(g.inliers, 0u);
  EXPECT_EQ(g.rms, 0.0);
  EXPECT_EQ(g.length_scale, 1.0);
}
