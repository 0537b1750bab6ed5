// The free-space check end to end (issue 13; docs/VERDICT.md "Free space"): indoor scans of
// one building registered onto another building's outdoor MMS passed before it (RMS 11 mm,
// "the result can be used") and now fail as "contradicted"; right pairs (an acceptance
// scenario, the real room pair with its PCD viewpoints) still succeed, with the evidence named
// in the verdict.
#include <gtest/gtest.h>

#include <iostream>

#include "acceptance_scenarios.hpp"
#include "io/io.hpp"
#include "registration/auto/registration_input.hpp"
#include "support/test_support.hpp"

using namespace plumb;

namespace {

const PointCloud& houseMms() {
  static const PointCloud c = test::presetOutdoorScan("house", 11);
  return c;
}

PipelineResult registerClouds(const PointCloud& source, const PointCloud& target) {
  RegistrationSide s, t;
  s.cloud = &source;
  t.cloud = &target;
  return registerData(s, t, PipelineParams{});
}

void expectContradicted(const std::string& preset) {
  const PointCloud indoor = test::presetIndoorScans(preset, 500);
  const PipelineResult r = registerClouds(indoor, houseMms());
  std::cout << preset << ": " << r.report.verdict << "\n";
  // The check runs only on a registration that succeeded without it: the wrong building
  // passed every other test (the bug of issue 13).
  EXPECT_TRUE(r.report.visibility.computed) << preset << ": " << r.report.verdict;
  EXPECT_FALSE(r.success()) << preset;
  EXPECT_EQ(r.report.status, "contradicted") << preset;
  EXPECT_GT(r.report.visibility.contradiction_ratio, PipelineParams{}.visibility.fail_ratio);
  EXPECT_NE(r.report.verdict.find("another building or a wrong placement"), std::string::npos);
}

}  // namespace

TEST(VisibilityVerdict, IndoorScansOfAnotherBuildingOntoTheHouseMmsAreContradicted) {
  expectContradicted("l-shaped");
  expectContradicted("office-floor");
}

TEST(VisibilityVerdict, AnAcceptanceScenarioStillSucceedsWithFreeSpaceAgreeing) {
  const PipelineParams p = test::acceptanceParams();
  const test::Scenario s = test::makeScenario("indoor-indoor", p);
  for (const auto& pose : test::randomPoses(2, 5)) {
    const test::CaseOutcome o = test::runPlumbCase(s, pose, p);
    EXPECT_TRUE(o.correct()) << o.verdict;
    ASSERT_TRUE(o.visibility.conclusive()) << o.verdict;
    EXPECT_LT(o.visibility.contradiction_ratio, p.visibility.warn_ratio);
    EXPECT_NE(o.verdict.find("Free space agrees"), std::string::npos) << o.verdict;
  }
}

TEST(VisibilityVerdict, TheRealRoomPairSucceedsWithItsViewpointsAsSensorOrigins) {
  const auto a = makeRegistrationInput(readDataset(test::sharedData("pcd/room_scan1.pcd")),
                                       RigidTransform());
  const auto b = makeRegistrationInput(readDataset(test::sharedData("pcd/room_scan2.pcd")),
                                       RigidTransform());
  ASSERT_TRUE(a.viewpoint && b.viewpoint);  // PCD VIEWPOINT 0 0 0, among the points
  const PipelineResult r = registerData(b.side(), a.side(), PipelineParams{});
  std::cout << qualityReportToText(r.report);
  ASSERT_TRUE(r.success()) << r.report.verdict;
  ASSERT_TRUE(r.report.visibility.conclusive());
  EXPECT_LT(r.report.visibility.contradiction_ratio, PipelineParams{}.visibility.warn_ratio);
  EXPECT_GT(r.report.visibility.expected_overlap, 0.3);
}

TEST(VisibilityVerdict, WithoutSensorOriginsTheVerdictSaysTheEvidenceIsMissing) {
  PointCloud a = readDataset(test::sharedData("pcd/room_scan1.pcd")).merged();
  PointCloud b = readDataset(test::sharedData("pcd/room_scan2.pcd")).merged();
  const PipelineResult r = registerClouds(b, a);  // merged clouds: no viewpoint
  ASSERT_TRUE(r.success()) << r.report.verdict;
  EXPECT_FALSE(r.report.visibility.conclusive());
  EXPECT_FALSE(r.report.visibility.source_in_target.available);
  EXPECT_NE(r.report.verdict.find("No free-space evidence"), std::string::npos)
      << r.report.verdict;
}
