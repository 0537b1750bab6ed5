#pragma once
// The pipeline's free-space check (issue 13): after refinement, the final transform is tested
// against the space each side's scanners saw through (quality/visibility_evidence.hpp); the
// evidence goes into assessRegistration, whose rule (quality/visibility_verdict.hpp) may fail
// or flag the report.
#include <optional>
#include <vector>

#include "quality/quality_report.hpp"
#include "quality/visibility_evidence.hpp"
#include "registration/auto/candidate_refinement.hpp"
#include "registration/auto/registration_pipeline.hpp"

namespace plumb {

/// Scan to scan: source points in the target's free space and target points in the source's;
/// scan to model: the source's rays against the model's structural surfaces. `source` must be
/// the scan (the pipeline swaps a model source to the target side first). Each direction's
/// `structure` judges the tested side's large planes (its features; none: unavailable).
VisibilitySummary checkVisibility(const RegistrationSide& source, const RegistrationSide& target,
                                  const RigidTransform& source_to_target,
                                  const VisibilityParams& params,
                                  const FeatureSet& source_features = {},
                                  const FeatureSet& target_features = {});

/// Free-space evidence of refined candidate placements (issue 13, symmetry): for each
/// hypothesis marked in `judge`, its summary and whether the free-space rule
/// (judgeFreeSpace) would fail it as contradicted. Hypotheses not judged stay not computed.
struct CandidateFreeSpace {
  std::vector<VisibilitySummary> summaries;  ///< one per hypothesis
  std::vector<bool> ruled_out;               ///< contradicted by the free space
  std::size_t judged = 0;
  std::size_t contradicted = 0;
};
CandidateFreeSpace judgeCandidatesByFreeSpace(const RegistrationSide& source,
                                              const RegistrationSide& target,
                                              const std::vector<RefinedHypothesis>& hypotheses,
                                              const std::vector<bool>& judge,
                                              const VisibilityParams& params,
                                              const FeatureSet& source_features,
                                              const FeatureSet& target_features);

/// The evidence of the result's final transform (refined when it was, else the global one)
/// with its features' planes, when params.enabled and the global step succeeded.
std::optional<VerdictEvidence> measureVerdictEvidence(const RegistrationSide& source,
                                                      const RegistrationSide& target,
                                                      const PipelineResult& result,
                                                      const VisibilityParams& params);

}  // namespace plumb
