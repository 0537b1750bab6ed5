#pragma once
// The free-space evidence in the quality report: the verdict rule, and the JSON and text of
// QualityReport::visibility. Kept apart from assessRegistration so the rule reads on its own.
#include <nlohmann/json_fwd.hpp>

#include <string>

#include "quality/quality_report.hpp"
#include "quality/visibility_evidence.hpp"

namespace plumb {

/// Applies q.visibility to a successful report: a contradiction ratio above
/// params.fail_ratio fails it (status "contradicted", the verdict names the figure and what it
/// means), one above params.warn_ratio adds a warning (check visually). Either way the verdict
/// says which evidence it rests on: the free-space figures, or why there are none.
void applyVisibilityEvidence(QualityReport& q, const VisibilityParams& params);

/// {"computed", "model_target", "contradiction_ratio", "expected_overlap",
///  "source_in_target": {...}, "target_in_source": {...}}; every figure of both directions.
void addVisibilityJson(nlohmann::json& report, const VisibilitySummary& summary);

/// Lines for qualityReportToText ("" when the check did not run).
std::string visibilityToText(const VisibilitySummary& summary);

}  // namespace plumb
