#pragma once
// The stations of a network run, one row each: name, state (reference, placed, not placed,
// ambiguous), position sigma, links in the adjustment, and a Lock check box (placed stations
// only): a locked station is held at its current adjusted pose at the next re-run.
#include <QTableWidget>

#include <memory>

#include "registration/network/network_registration.hpp"
#include "ui/network/network_session.hpp"

namespace plumb::ui {

class StationTable : public QTableWidget {
  Q_OBJECT
 public:
  enum Column { Name, State, Sigma, Links, Lock, Columns };
  explicit StationTable(QWidget* parent = nullptr);

  /// Fills the rows from the session's report; the locks from `decisions` (the next re-run's).
  void setSession(std::shared_ptr<const NetworkSession> session, const NetworkDecisions& decisions);
  int selectedStation() const;
  /// Selects row i (-1: none) without emitting stationSelected.
  void selectStation(int station);

 signals:
  void stationSelected(int station);
  void lockToggled(int station, bool locked);

 private:
  void fillRow(int row, const nlohmann::json& station, const NetworkSession& session, bool locked);
  bool filling_ = false;
};

/// The state column's word for station i of `session`.
QString stationState(const NetworkSession& session, std::size_t station);

}  // namespace plumb::ui
