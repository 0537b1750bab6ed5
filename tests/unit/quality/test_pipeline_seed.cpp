// The one seed (issue 18): PipelineParams::seed reaches the steps that draw at random (plane
// detection here), and the pipeline's result is deterministic for a seed.
#include <gtest/gtest.h>

#include "registration/auto/registration_pipeline.hpp"
#include "synthetic_scenes.hpp"

using namespace plumb;

namespace {

test::RoomSpec room() {
  test::RoomSpec s;
  s.outside = false;
  s.spacing = 0.05;
  return s;
}

/// Few hypotheses scored on a small random subset: the draws show in the inlier sets.
PipelineParams drawingParams(std::uint64_t seed) {
  PipelineParams p;
  p.plane_extraction.iterations = 10;
  p.plane_extraction.score_sample = 1000;
  p.plane_extraction.auto_threshold = false;
  p.seed = seed;
  return p;
}

}  // namespace

TEST(PipelineSeed, ReachesPlaneDetection) {
  const PointCloud cloud = test::makeRoom(room());
  const PipelineParams p1 = drawingParams(1);
  const auto planes1 = extractPlanes(cloud, p1.plane_extraction, 1).planes;
  // A seed whose draws differ from seed 1's.
  std::uint64_t other = 0;
  for (std::uint64_t s = 2; s <= 5 && !other; ++s) {
    const auto planes = extractPlanes(cloud, p1.plane_extraction, s).planes;
    if (planes.size() != planes1.size() || planes.front().inlier_count != planes1.front().inlier_count ||
        planes.front().offset != planes1.front().offset)
      other = s;
  }
  ASSERT_NE(other, 0u) << "seeds 2..5 all drew seed 1's planes";
  RegistrationSide side;
  side.cloud = &cloud;
  for (std::uint64_t s : {std::uint64_t{1}, other}) {
    const auto expected = extractPlanes(cloud, p1.plane_extraction, s).planes;
    const FeatureSet f = extractFeatures(side, drawingParams(s), false);
    ASSERT_EQ(f.planes.size(), expected.size()) << "seed " << s;
    for (std::size_t k = 0; k < expected.size(); ++k) {
      EXPECT_EQ(f.planes[k].inlier_count, expected[k].inlier_count) << "seed " << s;
      EXPECT_EQ(f.planes[k].offset, expected[k].offset) << "seed " << s;
    }
  }
}

TEST(PipelineSeed, SameSeedSameResult) {
  const PointCloud a = test::makeRoom(room());
  test::RoomSpec moved = room();
  moved.noise = 0.004;
  const PointCloud b = test::makeRoom(moved);
  RegistrationSide s, t;
  s.cloud = &a;
  t.cloud = &b;
  const PipelineParams p = drawingParams(3);
  const PipelineResult r1 = registerData(s, t, p);
  const PipelineResult r2 = registerData(s, t, p);
  EXPECT_EQ(r1.report.level, r2.report.level);
  EXPECT_EQ(r1.method_used, r2.method_used);
  EXPECT_TRUE(r1.transform().matrix() == r2.transform().matrix());
  EXPECT_EQ(r1.log, r2.log);
}
