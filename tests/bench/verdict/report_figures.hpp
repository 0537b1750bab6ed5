#pragma once
// Reads a quality report generically from its JSON (qualityReportToJson), so that evidence
// other engineers add to the report (a "visibility" object, "verdict_level", "candidates")
// shows up in bench_verdict's table without code changes.
#include <map>
#include <string>

#include "pair_record.hpp"

namespace plumb::verdict {

/// Every numeric leaf of the report, keyed by its path ("points.rms_m", "figures.x",
/// "runner_up.relative_gap"). Arrays of numbers give "<name>.min" and "<name>.max"; arrays of
/// objects give "<name>.count" and the leaves of their first element ("<name>[0].score"); other
/// arrays (strings: warnings) their "<name>.count".
/// Transforms (4x4 matrices), axes, timings ("seconds ...") and booleans are left out.
std::map<std::string, double> reportFigures(const std::string& report_json);

/// The verdict level: "verdict_level" when the report has it, else derived from success and
/// warnings (success without warnings = usable, with warnings = check visually, else failed).
Level reportLevel(const std::string& report_json);

}  // namespace plumb::verdict
