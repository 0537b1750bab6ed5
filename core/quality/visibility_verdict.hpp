#pragma once
// The free-space evidence in the quality report: the verdict rule, and the JSON and text of
// QualityReport::visibility. Kept apart from assessRegistration so the rule reads on its own;
// assessRegistration applies its finding while it composes the verdict.
#include <nlohmann/json_fwd.hpp>

#include <string>
#include <vector>

#include "quality/visibility_evidence.hpp"

namespace plumb {

/// What the free-space rule says about a registration that passed every other rule.
struct FreeSpaceFinding {
  /// The contradiction ratio is above VisibilityParams::fail_ratio: status "contradicted".
  bool contradicted = false;
  std::string failure;                ///< the whole verdict when contradicted
  std::vector<std::string> warnings;  ///< above warn_ratio (check visually)
  std::string evidence;  ///< sentence naming what the verdict rests on ("" when not computed)
};

/// The refinement's figures the free-space sentences quote.
struct FitFigures {
  bool refined = false;
  double overlap = 0.0;    ///< refined overlap ratio
  double point_rms = 0.0;  ///< m
};

/// The rule: a contradiction ratio above params.fail_ratio fails (the verdict names the figure
/// and what it means), one above params.warn_ratio is a warning. Either way `evidence` says
/// which evidence the verdict rests on: the free-space figures, or why there are none.
FreeSpaceFinding judgeFreeSpace(const VisibilitySummary& summary, const VisibilityParams& params,
                                const FitFigures& fit);

/// {"computed", "model_target", "contradiction_ratio", "expected_overlap",
///  "source_in_target": {...}, "target_in_source": {...}}; every figure of both directions.
void addVisibilityJson(nlohmann::json& report, const VisibilitySummary& summary);

/// Lines for qualityReportToText ("" when the check did not run).
std::string visibilityToText(const VisibilitySummary& summary);

}  // namespace plumb
