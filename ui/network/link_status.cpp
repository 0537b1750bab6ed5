#include "ui/network/link_status.hpp"

#include <nlohmann/json.hpp>

#include <QObject>

namespace plumb::ui {

LinkStatus linkStatus(const nlohmann::json& link) {
  // A rejected link is not accepted either: the surveyor's decision is what to show.
  if (link.value("decision", std::string()) == "rejected") return LinkStatus::Rejected;
  if (!link.contains("transform")) return LinkStatus::Failed;
  if (!link.value("accepted", false)) return LinkStatus::NotAccepted;
  if (link.value("dropped", false)) return LinkStatus::Dropped;
  if (link.value("flagged", false)) return LinkStatus::Flagged;
  if (link.value("bridge", false)) return LinkStatus::Bridge;
  return LinkStatus::Kept;
}

QString linkStatusName(LinkStatus status) {
  switch (status) {
    case LinkStatus::Kept: return QObject::tr("kept");
    case LinkStatus::Bridge: return QObject::tr("bridge");
    case LinkStatus::Flagged: return QObject::tr("flagged");
    case LinkStatus::Dropped: return QObject::tr("dropped");
    case LinkStatus::Rejected: return QObject::tr("rejected");
    case LinkStatus::NotAccepted: return QObject::tr("not accepted");
    case LinkStatus::Failed: return QObject::tr("failed");
  }
  return {};
}

QColor linkStatusColour(LinkStatus status) {
  switch (status) {
    case LinkStatus::Kept:
    case LinkStatus::Bridge: return QColor(40, 160, 60);
    case LinkStatus::Flagged: return QColor(240, 140, 0);
    case LinkStatus::Dropped: return QColor(210, 40, 40);
    case LinkStatus::Rejected: return QColor(120, 120, 120);
    case LinkStatus::NotAccepted:
    case LinkStatus::Failed: return QColor(200, 200, 200);
  }
  return {};
}

}  // namespace plumb::ui
