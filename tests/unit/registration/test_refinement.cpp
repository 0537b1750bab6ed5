// The quality report on refined results: weak directions, degenerate scenes, failures.
#include <gtest/gtest.h>

#include "quality/quality_report.hpp"
#include "registration/refine/icp_refinement.hpp"
#include "support/degenerate_scenes.hpp"
#include "unit/registration/refine_scenes.hpp"
#include "unit/registration/synthetic_building.hpp"

using namespace plumb;
using test::boxesMesh;
using test::noisyScan;

TEST(QualityReport, ACorridorWithoutOpeningsIsDegenerateAlongItsAxis) {
  // A long corridor without end walls: translation along X is unconstrained.
  TriangleMesh m;
  m.vertices = {{0, 0, 0}, {30, 0, 0}, {30, 2, 0}, {0, 2, 0},
                {0, 0, 3}, {30, 0, 3}, {30, 2, 3}, {0, 2, 3}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}, {4, 6, 5}, {4, 7, 6},  // floor, ceiling
                 {0, 1, 5}, {0, 5, 4}, {3, 7, 6}, {3, 6, 2}}; // side walls
  const PointCloud target = noisyScan(m, 0.08, 0.002, 4);
  PointCloud source = noisyScan(m, 0.08, 0.002, 5);
  const auto r = refineRegistration(source, target, RigidTransform(), {});
  GlobalRegistrationResult g;
  g.status = RegistrationStatus::Success;
  g.method = "test";
  const QualityReport q = assessRegistration(g, &r);
  EXPECT_FALSE(q.success) << q.verdict;
  EXPECT_EQ(q.status, "degenerate");
  ASSERT_FALSE(q.weak_directions.empty()) << q.verdict;
  EXPECT_TRUE(q.weak_directions[0].translation);
  EXPECT_TRUE(q.weak_directions[0].unconstrained);
  EXPECT_GT(std::abs(q.weak_directions[0].axis.x()), 0.95);
  EXPECT_NE(q.verdict.find("translation along horizontal (1.00"), std::string::npos) << q.verdict;
  const std::string json = qualityReportToJson(q);
  EXPECT_NE(json.find("\"unconstrained\": true"), std::string::npos);
  // A closed box has no weak direction: every slide pushes many points off their surface.
  const TriangleMesh box = boxesMesh(test::asymmetricRooms());
  const auto rb = refineRegistration(noisyScan(box, 0.08, 0.002, 6), noisyScan(box, 0.08, 0.002, 7),
                                     RigidTransform(), {});
  const QualityReport qb = assessRegistration(g, &rb);
  EXPECT_TRUE(qb.success) << qb.verdict;
  EXPECT_TRUE(qb.weak_directions.empty()) << qb.verdict;
  for (double resistance : rb.direction_resistance) EXPECT_GT(resistance, 0.1);
}


// Degenerate suite (issue 13): data that leaves degrees of freedom free never passes, even
// when ICP lands near the truth by chance; the report names at least as many free directions.
TEST(QualityReport, DegenerateScenesNeverSucceed) {
  using test::degenerateScenes;
  using test::noisyRectangles;
  GlobalRegistrationResult g;
  g.status = RegistrationStatus::Success;
  g.method = "icp";
  for (const auto& scene : degenerateScenes()) {
    const PointCloud target = noisyRectangles(scene.rects, 30000, 1);
    PointCloud source = noisyRectangles(scene.rects, 30000, 2);
    // The source is shifted along the free directions; ICP cannot see the shift.
    source.transform(RigidTransform::fromYaw(0.0, {0.3, -0.2, 0.0}));
    const auto r = refineRegistration(source, target, RigidTransform(), {});
    const QualityReport q = assessRegistration(g, &r);
    EXPECT_FALSE(q.success) << scene.name << ": " << q.verdict;
    EXPECT_EQ(q.status, "degenerate") << scene.name << ": " << q.verdict;
    int unconstrained = 0;
    for (const auto& w : q.weak_directions) unconstrained += w.unconstrained;
    EXPECT_GE(unconstrained, scene.free_directions) << scene.name << ": " << q.verdict;
  }
}

TEST(QualityReport, RefinementOffNeverClaimsWellConstrained) {
  GlobalRegistrationResult g;
  g.status = RegistrationStatus::Success;
  g.method = "planes";
  const QualityReport q = assessRegistration(g, nullptr);
  EXPECT_TRUE(q.success);
  EXPECT_EQ(q.verdict.find("well constrained"), std::string::npos) << q.verdict;
  EXPECT_NE(q.verdict.find("CHECK VISUALLY"), std::string::npos) << q.verdict;
  EXPECT_EQ(q.level, VerdictLevel::CheckVisually);
  EXPECT_EQ(verdictExitCode(q.level), 3);
}

TEST(QualityReport, FailedGlobalResultIsAFailureWithoutTransform) {
  GlobalRegistrationResult g;
  g.status = RegistrationStatus::Ambiguous;
  g.method = "planes";
  g.message = "two different transforms score almost the same";
  const QualityReport q = assessRegistration(g, nullptr);
  EXPECT_FALSE(q.success);
  EXPECT_NE(q.verdict.find("FAILED"), std::string::npos);
}

TEST(QualityReport, WrongAlignmentFailsOnOverlap) {
  const TriangleMesh mesh = boxesMesh(test::asymmetricRooms());
  const PointCloud target = noisyScan(mesh, 0.1, 0.003, 1);
  const PointCloud source = noisyScan(mesh, 0.1, 0.003, 2);
  GlobalRegistrationResult g;
  g.status = RegistrationStatus::Success;
  g.method = "test";
  g.transform = RigidTransform::fromYaw(0, {40, 40, 0});  // nowhere near
  const auto r = refineRegistration(source, target, g.transform, {});
  const QualityReport q = assessRegistration(g, &r);
  EXPECT_FALSE(q.success) << q.verdict;
}
