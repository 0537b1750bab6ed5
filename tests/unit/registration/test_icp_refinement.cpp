// The local refinement end to end (trimmed point-to-plane ICP and PCL GICP) and the mesh
// sampling it refines BIM targets against. Links the refinement only (no quality report), so
// that the ThreadSanitizer run (tests/unit/tsan) builds little.
#include <gtest/gtest.h>

#include "registration/refine/icp_refinement.hpp"
#include "unit/registration/refine_scenes.hpp"
#include "unit/registration/synthetic_building.hpp"

using namespace plumb;
using test::boxesMesh;
using test::noisyScan;

TEST(MeshSampling, DensityAndDeterminism) {
  const TriangleMesh m = boxesMesh({{{0, 0, 0}, {2, 3, 4}}});
  const PointCloud a = sampleMeshSurface(m, 0.1, 3), b = sampleMeshSurface(m, 0.1, 3);
  const double area = 2 * (2 * 3 + 2 * 4 + 3 * 4);
  EXPECT_NEAR(double(a.size()), area / 0.01, 0.05 * area / 0.01);
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(a.positions.back(), b.positions.back());
  EXPECT_TRUE(a.hasNormals());
}

TEST(IcpRefinement, ConvergesFromAFewDegreesAndDecimetres) {
  const TriangleMesh mesh = boxesMesh(test::asymmetricRooms());
  const PointCloud target = noisyScan(mesh, 0.07, 0.003, 1);
  const PointCloud source0 = noisyScan(mesh, 0.07, 0.003, 2);
  for (const RigidTransform& truth :
       {RigidTransform::fromYaw(0.6, {12, -7, 0.3}), RigidTransform::fromYaw(-2.5, {-3, 15, -1})}) {
    PointCloud source = source0;
    source.transform(truth.inverse());
    // Start 2° and 0.2 m away from the truth.
    const RigidTransform start = RigidTransform::fromYaw(0.035, {0.15, -0.12, 0.05}) * truth;
    const bool first = truth.translation().x() > 0;
    for (auto method : {RefineParams::Method::PointToPlane, RefineParams::Method::Gicp}) {
      if (method == RefineParams::Method::Gicp && !first) continue;  // GICP is slow: once
      RefineParams p;
      p.method = method;
      const auto r = refineRegistration(source, target, start, p);
      EXPECT_LT(RigidTransform::rotationErrorDeg(r.transform, truth), 0.1);
      EXPECT_LT(RigidTransform::translationError(r.transform, truth), 0.02);
      EXPECT_LT(r.rms, 0.01);
      EXPECT_GT(r.overlap, 0.8);
    }
  }
}

// "Results are deterministic for a given seed": the fit cost and the slide test sum over
// thousands of points in parallel; summed in whatever order the threads finish, their last
// digits changed from run to run (and with them the comparison of close candidates).
TEST(IcpRefinement, SameInputsGiveBitIdenticalFiguresOnEveryRun) {
  const TriangleMesh mesh = boxesMesh(test::asymmetricRooms());
  const PointCloud target = noisyScan(mesh, 0.05, 0.003, 1);
  const PointCloud source = noisyScan(mesh, 0.05, 0.003, 2);
  const RigidTransform start = RigidTransform::fromYaw(0.02, {0.05, -0.04, 0.01});
  const RefineParams p;
  const RefineResult first = refineRegistration(source, target, start, p);
  ASSERT_GT(first.source_points, 10000u);  // enough 512-point chunks for threads to interleave
  for (int run = 0; run < 5; ++run) {
    const RefineResult again = refineRegistration(source, target, start, p);
    EXPECT_EQ(again.fit_cost, first.fit_cost) << "run " << run;
    EXPECT_EQ(again.direction_resistance, first.direction_resistance) << "run " << run;
    EXPECT_EQ(again.transform.matrix(), first.transform.matrix()) << "run " << run;
  }
}
