// Same results from the GUI and the CLI (issue 18). The desktop app detects features first
// (extractFeatures with segments, shown as overlays) and registers with them; plumb-cli
// registers the clouds directly. auto decides itself when it needs segments (its last resort for
// two scans): both paths must reach that step and give the same transform for the same seed.
#include <gtest/gtest.h>

#include <algorithm>

#include "registration/auto/registration_pipeline.hpp"
#include "synthetic_scenes.hpp"

using namespace plumb;

namespace {

/// Planes and openings made to fail, so auto goes on to segments.
PipelineParams lastResortParams() {
  PipelineParams p;
  p.planes.min_score = 1e6;
  p.openings.min_matched_segments = 1e6;
  p.seed = 5;
  return p;
}

bool triedSegments(const PipelineResult& r) {
  return std::any_of(r.log.begin(), r.log.end(), [](const std::string& l) { return l.rfind("segments: ", 0) == 0; });
}

}  // namespace

TEST(PipelinePaths, CliAndGuiPathsGiveTheSameTransform) {
  test::RoomSpec a_spec;
  a_spec.outside = false;
  a_spec.spacing = 0.03;
  test::RoomSpec b_spec = a_spec;
  b_spec.noise = 0.004;
  const PointCloud a = test::makeRoom(a_spec), b = test::makeRoom(b_spec);
  const PipelineParams p = lastResortParams();

  // plumb-cli: the clouds only (makeRegistrationInput without features).
  RegistrationSide cs, ct;
  cs.cloud = &a;
  ct.cloud = &b;
  const PipelineResult cli = registerData(cs, ct, p);

  // Desktop app: "Detect features" (with segments), then "Register" with them.
  RegistrationSide gs = cs, gt = ct;
  const FeatureSet fs = extractFeatures(gs, p, true), ft = extractFeatures(gt, p, true);
  ASSERT_FALSE(fs.segments.empty());
  ASSERT_FALSE(ft.segments.empty());
  gs.features = &fs;
  gt.features = &ft;
  const PipelineResult gui = registerData(gs, gt, p);

  EXPECT_TRUE(triedSegments(cli)) << "the CLI path never reached the segments step";
  EXPECT_TRUE(triedSegments(gui));
  EXPECT_EQ(cli.method_used, gui.method_used);
  EXPECT_EQ(cli.report.level, gui.report.level);
  EXPECT_EQ(cli.global.status, gui.global.status);
  EXPECT_TRUE(cli.transform().matrix() == gui.transform().matrix())
      << cli.transform().matrix() << "\nvs\n" << gui.transform().matrix();
  // The segments the pipeline detected for the CLI path are those the app showed.
  EXPECT_EQ(cli.source_features.segments.size(), fs.segments.size());
  EXPECT_EQ(cli.target_features.segments.size(), ft.segments.size());
}

TEST(PipelinePaths, SegmentsAreDetectedOnlyWhenNeeded) {
  // Planes succeed: no segment detection for two scans (it costs seconds on real scans).
  test::RoomSpec spec;
  spec.outside = false;
  spec.spacing = 0.04;
  const PointCloud a = test::makeRoom(spec);
  RegistrationSide s, t;
  s.cloud = &a;
  t.cloud = &a;
  PipelineParams p;
  p.refine = false;
  p.planes.min_relative_gap = 0.01;  // a box room: the half turn scores 3 % lower
  const PipelineResult r = registerData(s, t, p);
  ASSERT_EQ(r.global.method, "planes") << r.global.message;
  ASSERT_TRUE(r.global.ok()) << r.global.message;
  EXPECT_FALSE(triedSegments(r));
  EXPECT_TRUE(r.source_features.segments.empty());
}
