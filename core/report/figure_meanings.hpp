#pragma once
// What each figure of the quality report (qualityReportToJson) means, in a surveyor's words,
// and how its value reads (units, counts as whole numbers, ratios as percentages).
#include <nlohmann/json_fwd.hpp>

#include <string>

namespace plumb::report {

/// A report path with array indices removed: "candidates[2].rms_m" -> "candidates[].rms_m".
std::string genericPath(const std::string& path);

/// The meaning of the figure at `path` (a JSON path as produced by flattenReport), or "" when
/// the report has no description for it.
std::string figureMeaning(const std::string& path);

/// The value as a reader wants it: "14.5 mm", "0.031 deg", "71.6 %", "20", "yes", "none".
std::string displayValue(const std::string& path, const nlohmann::json& value);

}  // namespace plumb::report
