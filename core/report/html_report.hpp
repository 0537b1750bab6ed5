#pragma once
// The registration report as one self-contained HTML file (inline CSS and SVG, no scripts, no
// external resources): verdict, inputs, transform, every figure of the quality report's JSON
// with its meaning, distance QA, per-feature residuals, candidates, pictures, sign-off block.
// Each figure's cell carries data-json="<path>" and data-value="<the JSON value>", so a test or
// a script can check the HTML against the JSON report exactly.
#include <string>

#include "report/registration_report.hpp"

namespace plumb::report {

std::string reportHtml(const RegistrationReport& report);

/// Every leaf of a JSON report as (path, value): objects by key ("points.rms_m"), arrays of
/// objects by index ("candidates[1].rms_m"); arrays of numbers or strings are one leaf.
std::vector<std::pair<std::string, std::string>> flattenReportJson(const std::string& json_text);

}  // namespace plumb::report
