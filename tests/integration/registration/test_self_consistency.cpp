// Self-consistency (issue 13) on the simulated indoor/indoor pair of the acceptance scenarios
// (house: a station in a room, one in the doorway to the next): a scan registered onto itself
// is the identity and usable; A onto B composed with B onto A is the identity within the
// acceptance accuracy (0.1 deg, 2 cm at the data), both ways usable.
// (The demo outdoor scan onto itself: CliIndoorOutdoor.DemoOutdoorOntoItselfIsTheIdentity;
// the real pair both ways: RealPair.RoomScansRegisterFromIdentityBothWays.)
#include <gtest/gtest.h>

#include "acceptance_scenarios.hpp"

using namespace plumb;
using namespace plumb::test;

namespace {
PipelineResult registerClouds(const PointCloud& source, const PointCloud& target,
                              const PipelineParams& params) {
  RegistrationSide s, t;
  s.cloud = &source;
  t.cloud = &target;
  const PipelineResult r = registerData(s, t, params);
  std::printf("%s", qualityReportToText(r.report).c_str());
  return r;
}
}  // namespace

TEST(SelfConsistency, IndoorScanOntoItselfIsTheIdentity) {
  const PipelineParams params = acceptanceParams();
  const Scenario s = makeScenario("indoor-indoor", params);
  const PipelineResult r = registerClouds(s.source, s.source, params);
  ASSERT_EQ(r.report.level, VerdictLevel::Usable) << r.report.verdict;
  const PoseError e = poseError(r.transform(), RigidTransform(), s.source.bounds().center());
  EXPECT_LT(e.rotation_deg, 1e-3);
  EXPECT_LT(e.translation_m, 1e-3);
}

TEST(SelfConsistency, IndoorPairBothWaysComposesToTheIdentity) {
  const PipelineParams params = acceptanceParams();
  const Scenario s = makeScenario("indoor-indoor", params);
  const PipelineResult ab = registerClouds(s.source, s.target, params);
  const PipelineResult ba = registerClouds(s.target, s.source, params);
  ASSERT_EQ(ab.report.level, VerdictLevel::Usable) << ab.report.verdict;
  ASSERT_EQ(ba.report.level, VerdictLevel::Usable) << ba.report.verdict;
  // The scans are simulated in the model frame: each direction is the identity too.
  const Eigen::Vector3d c = s.source.bounds().center();
  EXPECT_TRUE(withinTolerance(poseError(ab.transform(), RigidTransform(), c)));
  const PoseError loop = poseError(ba.transform() * ab.transform(), RigidTransform(), c);
  std::printf("A->B->A: %.4f deg, %.4f m at the source centroid\n", loop.rotation_deg,
              loop.translation_m);
  EXPECT_TRUE(withinTolerance(loop)) << loop.rotation_deg << " deg, " << loop.translation_m << " m";
}
