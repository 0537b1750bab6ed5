#pragma once
// The pipeline's free-space check (issue 13): after refinement, the final transform is tested
// against the space each side's scanners saw through (quality/visibility_evidence.hpp); the
// evidence goes into assessRegistration, whose rule (quality/visibility_verdict.hpp) may fail
// or flag the report.
#include <optional>

#include "quality/quality_report.hpp"
#include "quality/visibility_evidence.hpp"
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

/// The evidence of the result's final transform (refined when it was, else the global one)
/// with its features' planes, when params.enabled and the global step succeeded.
std::optional<VerdictEvidence> measureVerdictEvidence(const RegistrationSide& source,
                                                      const RegistrationSide& target,
                                                      const PipelineResult& result,
                                                      const VisibilityParams& params);

}  // namespace plumb
