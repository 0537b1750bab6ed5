// Symmetric placements (issue 13): the duplex (shared/data/ifc/duplex.ifc) holds two mirrored
// dwellings; a single TLS station in the living room of one of them fits the other one turned
// by a half turn about as well. Registered onto the whole model from random poses, the answer
// must never be written in the wrong copy: either the right placement, or failed/ambiguous
// with the right placement among the listed candidates.
#include <gtest/gtest.h>

#include <cstdio>

#include "acceptance_scenarios.hpp"

using namespace plumb;
using namespace plumb::test;

namespace {

/// Whether one of the report's candidates is the truth (acceptance tolerance).
bool truthAmongCandidates(const PipelineResult& r, const RigidTransform& truth,
                          const Eigen::Vector3d& centroid) {
  for (const auto& c : r.report.candidates)
    if (withinTolerance(poseError(c.transform, truth, centroid))) return true;
  return false;
}

void runUnit(const std::string& name, std::uint64_t seed) {
  const PipelineParams params = acceptanceParams();
  const Scenario s = makeScenario(name, params);
  ASSERT_GT(s.source.size(), 10000u);
  for (const RigidTransform& pose : randomPoses(2, seed)) {
    PointCloud moved = s.source;
    moved.transform(pose);
    RegistrationSide src, tgt;
    src.cloud = &moved;
    tgt.model = s.model.get();
    tgt.model_samples = &s.target_samples;
    tgt.features = &s.target_features;
    const PipelineResult r = registerData(src, tgt, params);
    const Eigen::Vector3d centroid = moved.bounds().center();
    const PoseError e = poseError(r.transform(), pose.inverse(), centroid);
    std::printf("%s: %s, %zu candidates, error %.4f deg %.4f m\n%s", name.c_str(),
                verdictLevelName(r.report.level), r.report.candidates.size(), e.rotation_deg,
                e.translation_m, qualityReportToText(r.report).c_str());
    if (r.success()) {
      EXPECT_TRUE(withinTolerance(e)) << name << ": results written in the wrong place, "
                                      << e.translation_m << " m from the truth";
    } else {
      EXPECT_EQ(r.report.status, "ambiguous") << r.report.verdict;
      EXPECT_GE(r.report.candidates.size(), 2u);
      EXPECT_TRUE(truthAmongCandidates(r, pose.inverse(), centroid)) << r.report.verdict;
    }
  }
}

}  // namespace

TEST(SymmetricPlacements, OneDuplexUnitIsNeverPlacedInTheOther) {
  runUnit("bim-duplex-unit-a", 31);
  runUnit("bim-duplex-unit-b", 32);
}
