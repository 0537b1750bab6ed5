#pragma once
// What became of a link of a network run, in one word, from its entry in the network report
// (networkReportToJson "links"): the tables, the plan view and the tests read it from here, so
// a link is never "kept" in one place and "flagged" in another.
#include <nlohmann/json_fwd.hpp>

#include <QColor>
#include <QString>

namespace plumb::ui {

enum class LinkStatus {
  Kept,         ///< in the adjustment, agrees with the network, checked by a loop
  Bridge,       ///< kept, but the only connection between two parts: nothing checks it
  Flagged,      ///< kept, its residual beyond the flag thresholds
  Dropped,      ///< removed by the robust loop
  Rejected,     ///< left out by the surveyor
  NotAccepted,  ///< registered, but its verdict keeps it out of the adjustment
  Failed,       ///< the pipeline gave no transform
};

LinkStatus linkStatus(const nlohmann::json& link);
QString linkStatusName(LinkStatus status);
/// Plan view colour: kept green, flagged orange, dropped red, rejected grey, others light grey.
QColor linkStatusColour(LinkStatus status);
/// The link takes part in the adjustment (kept, bridge or flagged).
inline bool inAdjustment(LinkStatus s) {
  return s == LinkStatus::Kept || s == LinkStatus::Bridge || s == LinkStatus::Flagged;
}

}  // namespace plumb::ui
