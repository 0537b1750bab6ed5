#pragma once
// The links of a network run, one row each: the two stations, the link's verdict, method,
// overlap, point RMS, weakest slide resistance, residual after the adjustment, status
// (link_status.hpp) and the surveyor's decision (as applied by the last adjustment, or pending
// until the next re-run).
#include <QTableWidget>

#include <memory>

#include "ui/network/link_decisions.hpp"
#include "ui/network/network_session.hpp"

namespace plumb::ui {

class LinkTable : public QTableWidget {
  Q_OBJECT
 public:
  enum Column { A, B, Verdict, Method, Overlap, Rms, Resistance, ResidualMm, ResidualDeg, Status, Decision, Columns };
  explicit LinkTable(QWidget* parent = nullptr);

  void setSession(std::shared_ptr<const NetworkSession> session, const NetworkDecisions& decisions);
  int selectedLink() const;
  /// Selects row k (-1: none) without emitting linkSelected.
  void selectLink(int link);

 signals:
  void linkSelected(int link);

 private:
  void fillRow(int row, const nlohmann::json& link, LinkDecision pending);
  bool filling_ = false;
};

/// The decision column: what the last adjustment applied and, when it differs, what the next
/// re-run will ("reject (re-run to apply)").
QString decisionText(const nlohmann::json& link, LinkDecision pending);

}  // namespace plumb::ui
