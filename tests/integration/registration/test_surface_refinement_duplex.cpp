// Refinement against the model's visible triangles on a real IFC model (issue 14): the duplex
// scenario (acceptance_scenarios.hpp: a TLS station in each dwelling's living room, 3 mm noise)
// moved by two random poses and registered end to end onto duplex.ifc lands within 0.01 deg
// and 3 mm of the truth (the refinement on points sampled on the model tilted by 0.05-0.07 deg,
// bench_surface_refine), and the refinement started at the truth stays within 0.01 deg.
#include <gtest/gtest.h>

#include <cstdio>

#include "acceptance_scenarios.hpp"

using namespace plumb;
using namespace plumb::test;

TEST(SurfaceRefinementDuplex, RegistersWithinOneHundredthOfADegree) {
  PipelineParams params = acceptanceParams();
  params.refinement.model_surface = RefineParams::ModelSurface::Triangles;
  const Scenario s = makeScenario("bim-duplex", params);
  const RefineTarget triangles(s.model->mesh, params.refinement);
  for (const RigidTransform& pose : randomPoses(2, 1414)) {
    const CaseOutcome o = runPlumbCase(s, pose, params);
    std::printf("pipeline: %s %s, %.4f deg, %.2f mm (%.1f s)\n", o.method.c_str(), o.level.c_str(),
                o.error.rotation_deg, 1000 * o.error.translation_m, o.seconds_total);
    ASSERT_TRUE(o.reported_success) << o.verdict;
    EXPECT_LT(o.error.rotation_deg, 0.01);
    EXPECT_LT(o.error.translation_m, 0.003);

    PointCloud moved = s.source;
    moved.transform(pose);
    const RigidTransform truth = pose.inverse();
    const RefineResult r = refineRegistration(moved, triangles, truth, params.refinement);
    const PoseError e = poseError(r.transform, truth, moved.bounds().center());
    std::printf("refined from the truth: %.4f deg, %.2f mm (%s)\n", e.rotation_deg,
                1000 * e.translation_m, r.surface.c_str());
    EXPECT_EQ(r.surface, "visible triangles");
    EXPECT_LT(e.rotation_deg, 0.01);
    EXPECT_LT(e.translation_m, 0.003);
  }
}
