// Acceptance of the registration engine (issue 6) on simulated data: for each scenario, 10
// random initial poses (yaw uniform in [-180, 180] deg, shift up to 20 m; the CI-sized subset:
// bench_registration and bench_verdict run more), 3 mm TLS range
// noise, end to end (cloud -> features -> global method -> refinement). Asserts
//  - success (rotation error < 0.1 deg and translation error < 2 cm) in >= 95% of cases;
//  - no confident wrong answer: every case outside the tolerance is reported as a failure.
// The scans are simulated once per scenario and moved by each pose (not re-simulated); the
// source features are extracted from the moved cloud every time, the fixed target's once.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <iostream>

#include "acceptance_scenarios.hpp"
#include "support/sanitized_build.hpp"

using namespace plumb;
using namespace plumb::test;

namespace {

constexpr int kPoses = repetitions(10, 2);  // 2 in the sanitizer tree (tests/sanitize)

void runScenario(const std::string& name, std::uint64_t seed) {
  const PipelineParams params = acceptanceParams();
  const Scenario s = makeScenario(name, params);
  std::printf("%s: source %zu points, target %s; simulation %.2f s, target features %.2f s\n",
              name.c_str(), s.source.size(),
              s.isBim() ? (std::to_string(s.target_features.segments.size()) + " model edges").c_str()
                        : (std::to_string(s.target.size()) + " points").c_str(),
              s.seconds_simulation, s.seconds_target_features);
  ASSERT_GT(s.source.size(), 10000u);
  const auto poses = randomPoses(kPoses, seed);
  int correct = 0, confident_wrong = 0;
  double least_resistance = std::numeric_limits<double>::infinity();
  double seconds = 0.0;
  for (int i = 0; i < kPoses; ++i) {
    const CaseOutcome o = runPlumbCase(s, poses[i], params);
    std::printf("  case %2d: yaw %7.1f deg shift %5.1f m -> %-8s %-14s rot %.4f deg trans %.4f m "
                "slide resistance %.3f (features %.2f s, global %.2f s, refine %.2f s)\n",
                i, poses[i].rotationAngleDeg() * (poses[i].rotation()(1, 0) < 0 ? -1 : 1),
                poses[i].translation().norm(), o.method.c_str(), o.level.c_str(), o.error.rotation_deg,
                o.error.translation_m, o.min_resistance, o.seconds_features, o.seconds_global,
                o.seconds_refine);
    if (o.correct()) least_resistance = std::min(least_resistance, o.min_resistance);
    if (!o.reported_success) std::printf("           %s\n", o.verdict.c_str());
    if (!o.candidates.empty()) std::printf("           candidates: %s\n", o.candidates.c_str());
    seconds += o.seconds_total;
    correct += o.correct();
    confident_wrong += o.confidentWrong();
    EXPECT_FALSE(o.confidentWrong())
        << name << " case " << i << ": reported success but rotation error "
        << o.error.rotation_deg << " deg, translation error " << o.error.translation_m << " m";
  }
  std::printf("%s: %d/%d within 0.1 deg / 2 cm, %d confident wrong answers, least slide "
              "resistance of a right answer %.3f (degenerate below %.3f), %.2f s per case\n",
              name.c_str(), correct, kPoses, confident_wrong, least_resistance,
              params.quality.min_resistance, seconds / kPoses);
  EXPECT_GE(correct, (95 * kPoses + 99) / 100) << name << ": success rate below 95%";
}

}  // namespace

TEST(RegistrationAcceptance, IndoorIndoorTwoStations) { runScenario("indoor-indoor", 11); }
TEST(RegistrationAcceptance, IndoorOutdoorTlsToMms) { runScenario("indoor-outdoor", 12); }
TEST(RegistrationAcceptance, ScanToGeneratedBim) { runScenario("bim-generated", 13); }
TEST(RegistrationAcceptance, ScanToDuplexIfc) { runScenario("bim-duplex", 14); }
