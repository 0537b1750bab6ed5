#pragma once
// The georeference of a network run in the Network dock, from its report's "georeference"
// object (networkReportToJson, the one source of the figures): done or not and why, the grid
// scale factor used, and one row per control and check point with its residual (adjusted minus
// given, grid E, N, H and 3D, mm); check points are marked, being the ones that sign the work off.
#include <nlohmann/json.hpp>

#include <QWidget>

class QLabel;
class QTableWidget;

namespace plumb::ui {

class GeoreferenceView : public QWidget {
  Q_OBJECT
 public:
  enum Column { Point, Role, Stations, East, North, Height, Residual, Columns };
  explicit GeoreferenceView(QWidget* parent = nullptr);

  /// Shows `report`'s georeference (none: the run had no control points).
  void setReport(const nlohmann::json& report);
  void clear();
  const QTableWidget& points() const { return *points_; }
  QString status() const;
  QString scaleFactor() const;

 private:
  void fillRow(int row, const nlohmann::json& point);
  QLabel* status_;
  QLabel* scale_;
  QTableWidget* points_;
};

/// A residual in mm as the dock shows it (0.01 mm: the simulations' residuals are far below 1 mm).
QString residualMm(double metres);
/// The grid scale factor as the dock shows it (1e-8: PROJ's factor changes by 4e-9 per metre).
QString scaleFactorText(double k);

}  // namespace plumb::ui
