#include "registration/auto/visibility_check.hpp"


namespace plumb {

VisibilitySummary checkVisibility(const RegistrationSide& source, const RegistrationSide& target,
                                  const RigidTransform& t, const VisibilityParams& p) {
  VisibilitySummary s;
  s.computed = true;
  if (!source.cloud) return s;
  if (target.isModel()) {
    s.model_target = true;
    s.source_in_target = modelRayEvidence(*source.cloud, source.viewpoint, *target.model, t, p);
  } else if (target.cloud) {
    s.source_in_target = freeSpaceEvidence(*target.cloud, target.viewpoint, *source.cloud,
                                             source.viewpoint, t, p);
    s.source_in_target.what = "source points in the target's free space";
    if (!s.source_in_target.available)
      s.source_in_target.missing_reason = "the target has " + s.source_in_target.missing_reason;
    s.target_in_source =
        freeSpaceEvidence(*source.cloud, source.viewpoint, *target.cloud,
                                           target.viewpoint, t.inverse(), p);
    s.target_in_source.what = "target points in the source's free space";
    if (!s.target_in_source.available)
      s.target_in_source.missing_reason = "the source has " + s.target_in_source.missing_reason;
  }
  summarizeVisibility(s, p);
  return s;
}

std::optional<VerdictEvidence> measureVerdictEvidence(const RegistrationSide& source,
                                                      const RegistrationSide& target,
                                                      const GlobalRegistrationResult& g,
                                                      const RefineResult* refined,
                                                      const VisibilityParams& p) {
  if (!p.enabled || !g.ok()) return std::nullopt;
  const RigidTransform& t = refined ? refined->transform : g.transform;
  return VerdictEvidence{checkVisibility(source, target, t, p), p};
}

}  // namespace plumb
