#pragma once
// The network registration report as one self-contained HTML file (inline CSS and SVG), built
// from the JSON report of plumb-cli network (registration/network/network_report.hpp): the
// verdict, a plan view of the stations and links coloured by status, the station and link
// tables, the histogram of the kept links' residuals, every network figure, a sign-off block.
// Cells taken from the JSON carry data-json="<path>" data-value="<JSON value>" (as in the
// registration report), so a test or a script can check the HTML against the JSON exactly.
#include <nlohmann/json_fwd.hpp>

#include <string>

namespace plumb::report {

/// `created_utc`: when the report was made (ISO 8601), shown in the header.
std::string networkReportHtml(const nlohmann::json& report, const std::string& created_utc);

}  // namespace plumb::report
