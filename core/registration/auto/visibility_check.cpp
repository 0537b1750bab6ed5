#include "registration/auto/visibility_check.hpp"

#include "quality/structure_evidence.hpp"
#include "quality/visibility_verdict.hpp"

namespace plumb {

namespace {

/// One scan/scan direction: `tested` points in `observer`'s free space, and the tested side's
/// large planes judged one by one.
VisibilityEvidence scanDirection(const RegistrationSide& observer, const RegistrationSide& tested,
                                 const FeatureSet& tested_features, const RigidTransform& t,
                                 const VisibilityParams& p) {
  TestedSightings sightings;
  VisibilityEvidence e = freeSpaceEvidence(*observer.cloud, observer.viewpoint, *tested.cloud,
                                           tested.viewpoint, t, p, &sightings);
  if (e.available)
    e.structure = structureEvidence(tested_features.planes, tested.cloud->size(), sightings, p);
  return e;
}

}  // namespace

VisibilitySummary checkVisibility(const RegistrationSide& source, const RegistrationSide& target,
                                  const RigidTransform& t, const VisibilityParams& p,
                                  const FeatureSet& source_features,
                                  const FeatureSet& target_features) {
  VisibilitySummary s;
  s.computed = true;
  if (!source.cloud) return s;
  if (target.isModel()) {
    s.model_target = true;
    TestedSightings sightings;
    s.source_in_target =
        modelRayEvidence(*source.cloud, source.viewpoint, target.evidenceModel(), t, p, &sightings);
    if (s.source_in_target.available)
      s.source_in_target.structure =
          structureEvidence(source_features.planes, source.cloud->size(), sightings, p);
  } else if (target.cloud) {
    s.source_in_target = scanDirection(target, source, source_features, t, p);
    s.source_in_target.what = "source points in the target's free space";
    if (!s.source_in_target.available)
      s.source_in_target.missing_reason = "the target has " + s.source_in_target.missing_reason;
    s.target_in_source = scanDirection(source, target, target_features, t.inverse(), p);
    s.target_in_source.what = "target points in the source's free space";
    if (!s.target_in_source.available)
      s.target_in_source.missing_reason = "the source has " + s.target_in_source.missing_reason;
  }
  summarizeVisibility(s, p);
  return s;
}

CandidateFreeSpace judgeCandidatesByFreeSpace(const RegistrationSide& source,
                                              const RegistrationSide& target,
                                              const std::vector<RefinedHypothesis>& hypotheses,
                                              const std::vector<bool>& judge,
                                              const VisibilityParams& p,
                                              const FeatureSet& source_features,
                                              const FeatureSet& target_features) {
  CandidateFreeSpace c;
  c.summaries.resize(hypotheses.size());
  c.ruled_out.assign(hypotheses.size(), false);
  for (std::size_t i = 0; i < hypotheses.size(); ++i) {
    if (i >= judge.size() || !judge[i]) continue;
    const RefineResult& r = hypotheses[i].refined;
    c.summaries[i] =
        checkVisibility(source, target, r.transform, p, source_features, target_features);
    c.ruled_out[i] = judgeFreeSpace(c.summaries[i], p, FitFigures{true, r.overlap, r.rms}).contradicted;
    ++c.judged;
    if (c.ruled_out[i]) ++c.contradicted;
  }
  return c;
}

std::optional<VerdictEvidence> measureVerdictEvidence(const RegistrationSide& source,
                                                      const RegistrationSide& target,
                                                      const PipelineResult& result,
                                                      const VisibilityParams& p) {
  const GlobalRegistrationResult& g = result.global;
  if (!p.enabled || !g.ok()) return std::nullopt;
  const RigidTransform& t = result.refinement ? result.refinement->transform : g.transform;
  return VerdictEvidence{checkVisibility(source, target, t, p, result.source_features,
                                         result.target_features),
                         p};
}

}  // namespace plumb
