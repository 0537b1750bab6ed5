// Degenerate suite: scenes that leave degrees of freedom free (support/degenerate_scenes.hpp,
// shared with the refinement unit test) registered end to end, with `icp` and `auto`. A
// success is always wrong here.
#include <cstdio>

#include "pair_runner.hpp"
#include "suites.hpp"
#include "support/degenerate_scenes.hpp"

namespace plumb::verdict {

namespace {

PairRecord degenerateRecord(const test::DegenerateScene& scene, RegistrationMethod method,
                            const RigidTransform& shift, int i, const PipelineParams& base) {
  const PointCloud target = test::noisyRectangles(scene.rects, 30000, 1);
  PointCloud source = test::noisyRectangles(scene.rects, 30000, 2);
  source.transform(shift);
  SideData s, t;
  s.cloud = std::move(source);
  t.cloud = target;
  PipelineParams params = base;
  params.method = method;
  if (method != RegistrationMethod::Icp) {
    RegistrationSide rs, rt;
    rs.cloud = &s.cloud;
    rt.cloud = &t.cloud;
    s.features = extractFeatures(rs, params, false);
    t.features = extractFeatures(rt, params, false);
  }
  const PairOutcome o = registerMoved(s, RigidTransform(), t, params);
  PairRecord r = recordOf("degenerate", std::string(scene.name) + " (" + methodName(method) + ")",
                          i, o);
  r.group = "degenerate";
  r.correct = !r.success;
  r.confident_wrong = r.level == Level::Usable;
  std::printf("  [degenerate] %-40s case %d: %-19s %-12s %.1f s\n", r.pair.c_str(), i,
              levelName(r.level).c_str(), r.status.c_str(), r.seconds);
  std::fflush(stdout);
  return r;
}

}  // namespace

std::vector<PairRecord> runDegenerateSuite(const PipelineParams& params, bool full) {
  std::vector<RigidTransform> shifts{RigidTransform::fromYaw(0.0, {0.3, -0.2, 0.0})};
  if (full) shifts.push_back(RigidTransform::fromYaw(0.05, {-0.5, 0.4, 0.0}));
  std::vector<PairRecord> out;
  for (const auto& scene : test::degenerateScenes())
    for (auto method : {RegistrationMethod::Icp, RegistrationMethod::Auto})
      for (std::size_t i = 0; i < shifts.size(); ++i)
        out.push_back(degenerateRecord(scene, method, shifts[i], int(i), params));
  return out;
}

}  // namespace plumb::verdict
