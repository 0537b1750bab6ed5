#pragma once
// "Save report..." of the Network dock: the network report as plumb-cli network --report
// writes it, JSON (networkReportToJson) or, for a path ending in .html, the HTML report to
// hand over (report::networkReportHtml), written atomically (an existing file is replaced
// only once the new one is complete).
#include <nlohmann/json_fwd.hpp>

#include <filesystem>

namespace plumb::ui {

/// Throws on a write failure (the target stays as it was).
void saveNetworkReport(const std::filesystem::path& path, const nlohmann::json& report);

}  // namespace plumb::ui
