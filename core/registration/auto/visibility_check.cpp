#include "registration/auto/visibility_check.hpp"

#include "quality/visibility_verdict.hpp"

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

void addVisibilityEvidence(const RegistrationSide& source, const RegistrationSide& target,
                           const VisibilityParams& p, QualityReport& report) {
  if (!p.enabled || !report.success) return;
  report.visibility = checkVisibility(source, target, report.transform, p);
  applyVisibilityEvidence(report, p);
}

}  // namespace plumb
