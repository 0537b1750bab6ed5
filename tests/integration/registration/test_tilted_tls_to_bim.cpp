// Simulated TLS stations with an arbitrary 3D rotation register onto the model (issue 14): the
// "house" preset's ground-floor stations (acceptance_scenarios.hpp, "bim-generated"), moved by
// random rotations drawn uniformly on the sphere of rotations (any tilt, any yaw) and a shift,
// register onto the generated model as well as the same stations moved by levelled poses do
// (within 0.1 deg / 2 cm of the truth), and none is a confident wrong answer.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cstdio>

#include "acceptance_scenarios.hpp"

using namespace plumb;
using namespace plumb::test;

namespace {

double tiltDeg(const RigidTransform& t) {
  return std::acos(std::clamp(t.rotation()(2, 2), -1.0, 1.0)) * 180.0 / M_PI;
}

/// Cases within tolerance; fails the test on a confident wrong answer.
int correctCases(const Scenario& s, const std::vector<RigidTransform>& poses, const char* kind) {
  int correct = 0;
  for (const RigidTransform& pose : poses) {
    const CaseOutcome o = runPlumbCase(s, pose, acceptanceParams());
    std::printf("%s: tilt %5.1f deg -> %-8s %-14s rot %.4f deg trans %.4f m (%.2f s)\n", kind,
                tiltDeg(pose), o.method.c_str(), o.level.c_str(), o.error.rotation_deg,
                o.error.translation_m, o.seconds_total);
    EXPECT_FALSE(o.confidentWrong()) << kind << " tilt " << tiltDeg(pose) << ": " << o.verdict;
    correct += o.correct();
  }
  return correct;
}

}  // namespace

TEST(TiltedTlsToBim, ArbitraryRotationsRegisterAsWellAsLevelledOnes) {
  const Scenario s = makeScenario("bim-generated", acceptanceParams());
  const int levelled = correctCases(s, randomPoses(2, 41), "levelled");
  const int tilted = correctCases(s, randomPoses3d(3, 42), "arbitrary 3D");
  EXPECT_EQ(levelled, 2);
  EXPECT_EQ(tilted, 3);  // every one, as every levelled one
}
