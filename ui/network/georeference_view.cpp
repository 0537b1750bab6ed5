#include "ui/network/georeference_view.hpp"

#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>

#include "ui/network/row_table.hpp"

namespace plumb::ui {

QString residualMm(double metres) { return QString::number(metres * 1000.0, 'f', 2); }

GeoreferenceView::GeoreferenceView(QWidget* parent)
    : QWidget(parent), status_(new QLabel(this)), scale_(new QLabel(this)), points_(new QTableWidget(this)) {
  setObjectName("networkGeoreference");
  status_->setObjectName("georeferenceStatus");
  status_->setWordWrap(true);
  scale_->setObjectName("georeferenceScale");
  points_->setObjectName("georeferencePoints");
  points_->setColumnCount(Columns);
  points_->setHorizontalHeaderLabels(
      {tr("Point"), tr("Role"), tr("Stations"), tr("dE (mm)"), tr("dN (mm)"), tr("dH (mm)"), tr("Residual (mm)")});
  row_table::setUp(*points_);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(status_);
  layout->addWidget(scale_);
  layout->addWidget(points_, 1);
  clear();
}

void GeoreferenceView::clear() {
  status_->setText(tr("No control points given: the network is in its reference's frame"));
  scale_->clear();
  points_->setRowCount(0);
}

void GeoreferenceView::setReport(const nlohmann::json& report) {
  if (!report.contains("georeference")) return clear();
  const auto& g = report["georeference"];
  const QString message = QString::fromStdString(g["message"].get<std::string>());
  status_->setText(g["done"].get<bool>() ? tr("Georeference done: %1").arg(message)
                                         : tr("Not georeferenced: %1").arg(message));
  const std::string crs = g.value("crs", std::string());
  scale_->setText(tr("Grid scale factor %1%2")
                      .arg(scaleFactorText(g["scale_factor"].get<double>()))
                      .arg(crs.empty() ? QString() : tr(" (%1, from PROJ)").arg(QString::fromStdString(crs))));
  points_->setRowCount(int(g["points"].size()));
  for (int row = 0; row < points_->rowCount(); ++row) fillRow(row, g["points"][std::size_t(row)]);
}

void GeoreferenceView::fillRow(int row, const nlohmann::json& p) {
  const bool check = p["role"] == "check";
  const bool seen = p["observations"].get<int>() > 0;
  QStringList cells{QString::fromStdString(p["name"].get<std::string>()), check ? tr("check") : tr("control"),
                    QString::number(p["observations"].get<int>())};
  for (int a = 0; a < 3; ++a) cells << (seen ? residualMm(p["residual_grid_m"][std::size_t(a)].get<double>()) : "");
  cells << (seen ? residualMm(p["residual_m"].get<double>()) : tr("not seen"));
  for (int c = 0; c < Columns; ++c) {
    QTableWidgetItem* item = row_table::cell(cells[c]);
    if (check) item->setBackground(QColor(255, 244, 214));  // the sign-off rows stand out
    if (c >= East) item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
    points_->setItem(row, c, item);
  }
}

QString GeoreferenceView::status() const { return status_->text(); }
QString GeoreferenceView::scaleFactor() const { return scale_->text(); }

QString scaleFactorText(double k) { return QString::number(k, 'f', 8); }

}  // namespace plumb::ui
