#pragma once
// The pipeline's free-space check (issue 13): after refinement, the final transform is tested
// against the space each side's scanners saw through (quality/visibility_evidence.hpp), and
// the verdict rule (quality/visibility_verdict.hpp) may fail or flag the report.
#include "quality/quality_report.hpp"
#include "quality/visibility_evidence.hpp"
#include "registration/auto/registration_pipeline.hpp"

namespace plumb {

/// Scan to scan: source points in the target's free space and target points in the source's;
/// scan to model: the source's rays against the model's structural surfaces. `source` must be
/// the scan (the pipeline swaps a model source to the target side first).
VisibilitySummary checkVisibility(const RegistrationSide& source, const RegistrationSide& target,
                                  const RigidTransform& source_to_target,
                                  const VisibilityParams& params);

/// When params.enabled and the report is a success: checkVisibility on report.transform,
/// stored in report.visibility, then applyVisibilityEvidence.
void addVisibilityEvidence(const RegistrationSide& source, const RegistrationSide& target,
                           const VisibilityParams& params, QualityReport& report);

}  // namespace plumb
