#include "ui/network/network_session.hpp"

#include <QObject>

#include "registration/network/network_report.hpp"

namespace plumb::ui {

void NetworkSession::setResult(std::shared_ptr<const NetworkResult> r) {
  result = std::move(r);
  report = networkReportToJson(*result, *stations);
}

QString networkSummary(const nlohmann::json& report) {
  int placed = 0, stations = 0;
  for (const auto& s : report["stations"]) {
    if (s.value("model", false)) continue;
    ++stations;
    placed += s["placed"].get<bool>();
  }
  const auto& n = report["network"];
  return QObject::tr("%1 of %2 stations placed, %3 links in the adjustment, %4 dropped, %5 flagged")
      .arg(placed)
      .arg(stations)
      .arg(n.value("links_accepted", 0))
      .arg(n.contains("links_dropped") ? int(n["links_dropped"].size()) : 0)  // the dropped links, listed
      .arg(n.value("links_flagged", 0));
}

}  // namespace plumb::ui
