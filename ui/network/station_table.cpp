#include "ui/network/station_table.hpp"

#include <QHeaderView>

#include "ui/network/link_status.hpp"
#include "ui/network/row_table.hpp"

namespace plumb::ui {

namespace {

using row_table::cell;

/// Length of the position sigma vector, mm ("" when the station has none).
QString sigmaMm(const nlohmann::json& station) {
  if (!station.contains("sigma_position_m")) return {};
  double sum = 0;
  for (const auto& v : station["sigma_position_m"]) sum += v.get<double>() * v.get<double>();
  return QString::number(1000.0 * std::sqrt(sum), 'f', 2);
}

int linksInAdjustment(const nlohmann::json& station, const nlohmann::json& links) {
  int n = 0;
  for (const auto& k : station["links"]) n += inAdjustment(linkStatus(links[k.get<std::size_t>()]));
  return n;
}

}  // namespace

QString stationState(const NetworkSession& session, std::size_t station) {
  const NetworkResult& r = *session.result;
  if (r.isAmbiguous(station)) return QObject::tr("ambiguous");
  if (!r.placed(station)) return QObject::tr("not placed");
  return station == r.reference ? QObject::tr("reference") : QObject::tr("placed");
}

StationTable::StationTable(QWidget* parent) : QTableWidget(0, Columns, parent) {
  setObjectName("networkStations");
  setHorizontalHeaderLabels({tr("Station"), tr("State"), tr("σ position (mm)"), tr("Links"), tr("Lock")});
  horizontalHeaderItem(Sigma)->setToolTip(tr("Standard deviation of the station's position from the adjustment"));
  horizontalHeaderItem(Links)->setToolTip(tr("Links in the adjustment (kept, bridge or flagged)"));
  horizontalHeaderItem(Lock)->setToolTip(tr("Hold the station at its current adjusted pose at the next re-run"));
  row_table::setUp(*this);
  connect(this, &QTableWidget::itemSelectionChanged, this, [this] {
    if (!filling_) emit stationSelected(selectedStation());
  });
  connect(this, &QTableWidget::itemChanged, this, [this](QTableWidgetItem* item) {
    if (!filling_ && item->column() == Lock) emit lockToggled(item->row(), item->checkState() == Qt::Checked);
  });
}

void StationTable::setSession(std::shared_ptr<const NetworkSession> session, const NetworkDecisions& decisions) {
  const int selected = selectedStation();
  filling_ = true;
  setRowCount(session ? int(session->stationCount()) : 0);
  for (int i = 0; i < rowCount(); ++i)
    fillRow(i, session->report["stations"][std::size_t(i)], *session, decisions.locked.count(std::size_t(i)) > 0);
  filling_ = false;
  selectStation(selected < rowCount() ? selected : -1);
}

void StationTable::fillRow(int row, const nlohmann::json& station, const NetworkSession& session, bool locked) {
  setItem(row, Name, cell(QString::fromStdString(station["name"].get<std::string>())));
  QTableWidgetItem* state = cell(stationState(session, std::size_t(row)));
  for (const char* why : {"ambiguous_why", "unplaced_why"})
    if (station.contains(why)) state->setToolTip(QString::fromStdString(station[why].get<std::string>()));
  if (station.contains("free_space")) {  // what the free space of the confirmed stations decided
    const QString judged = QString::fromStdString(station["free_space"]["why"].get<std::string>());
    state->setToolTip(state->toolTip().isEmpty() ? judged : state->toolTip() + "\n" + judged);
  }
  if (station.value("unchecked", false) && !(station.contains("free_space") && station["free_space"]["settled"].get<bool>()))
    state->setToolTip(tr("Placed by one link no loop checks; the free space of the confirmed stations did not confirm "
                         "it: check it visually") +
                      (state->toolTip().isEmpty() ? QString() : "\n" + state->toolTip()));
  if (station.contains("placed_by"))
    state->setToolTip(tr("Placed by its own control points: no kept link joins it to the reference"));
  else if (station.value("settled_by_control", false))
    state->setToolTip(tr("Confirmed by the 3 or more control points it sees"));
  if (!session.result->placed(std::size_t(row))) state->setForeground(QColor(190, 30, 30));
  setItem(row, State, state);
  setItem(row, Sigma, cell(sigmaMm(station)));
  setItem(row, Links, cell(QString::number(linksInAdjustment(station, session.report["links"]))));
  QTableWidgetItem* lock = cell({});
  const bool lockable = session.result->placed(std::size_t(row)) && std::size_t(row) != session.result->reference;
  if (lockable && !station.value("model", false)) {
    lock->setFlags(lock->flags() | Qt::ItemIsUserCheckable);
    lock->setCheckState(locked ? Qt::Checked : Qt::Unchecked);
  }
  setItem(row, Lock, lock);
}

int StationTable::selectedStation() const { return row_table::selectedRow(*this); }

void StationTable::selectStation(int station) { row_table::selectQuietly(*this, station); }

}  // namespace plumb::ui
