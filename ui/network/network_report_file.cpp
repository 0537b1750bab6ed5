#include "ui/network/network_report_file.hpp"

#include <nlohmann/json.hpp>

#include "common/atomic_file.hpp"
#include "report/network_html.hpp"
#include "report/report_builder.hpp"

namespace plumb::ui {

void saveNetworkReport(const std::filesystem::path& path, const nlohmann::json& report) {
  writeFileAtomically(path, [&](std::ostream& out) {
    if (path.extension() == ".html") out << report::networkReportHtml(report, report::nowUtc());
    else out << report.dump(2) << "\n";
  });
}

}  // namespace plumb::ui
