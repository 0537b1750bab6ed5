#include "ui/panels/properties_panel.hpp"

#include <QColor>
#include <QHeaderView>
#include <QIcon>
#include <QPixmap>
#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>

#include "ui/layers/dataset_layer.hpp"
#include "ui/layers/model_layer.hpp"
#include "ui/panels/mesh_style_editor.hpp"
#include "ui/panels/point_style_editor.hpp"

namespace plumb::ui {

PropertiesPanel::PropertiesPanel(Scene& scene, QWidget* parent)
    : QWidget(parent),
      title_(new QLabel(this)),
      table_(new QTableWidget(0, 2, this)),
      points_(new PointStyleEditor(scene, this)),
      mesh_(new MeshStyleEditor(scene, this)) {
  setObjectName("propertiesPanel");
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(title_);
  layout->addWidget(points_);
  layout->addWidget(mesh_);
  layout->addWidget(table_, 1);
  table_->setObjectName("propertiesTable");
  table_->setHorizontalHeaderLabels({tr("Property"), tr("Value")});
  table_->horizontalHeader()->setStretchLastSection(true);
  table_->verticalHeader()->hide();
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  connect(points_, &PointStyleEditor::styleApplied, this, [this] {
    if (Layer* layer = current_.get()) {
      showRows(layer->name(), layer->describe());
      appendLegend(layer->legend());
    }
  });
  showLayer(nullptr);
}

void PropertiesPanel::showLayer(Layer* layer) {
  current_ = layer ? LayerRef(*layer) : LayerRef();
  auto* dataset = layer && layer->kind() == LayerKind::Dataset ? static_cast<DatasetLayer*>(layer)
                                                               : nullptr;
  auto* model = layer && layer->kind() == LayerKind::Model ? static_cast<ModelLayer*>(layer)
                                                           : nullptr;
  points_->setLayer(dataset);
  points_->setVisible(dataset != nullptr);
  mesh_->setLayer(model);
  mesh_->setVisible(model != nullptr);
  showRows(layer ? layer->name() : tr("No layer selected"),
           layer ? layer->describe() : std::vector<PropertyRow>{});
  if (layer) appendLegend(layer->legend());
}

void PropertiesPanel::appendLegend(const std::vector<LegendEntry>& legend) {
  for (const auto& entry : legend) {
    const int row = table_->rowCount();
    table_->insertRow(row);
    const QColor colour(entry.colour[0], entry.colour[1], entry.colour[2]);
    QPixmap swatch(12, 12);
    swatch.fill(colour);
    auto* label = new QTableWidgetItem(QIcon(swatch), entry.label);
    label->setToolTip(tr("Colour in the view"));
    table_->setItem(row, 0, label);
    table_->setItem(row, 1, new QTableWidgetItem(colour.name()));
  }
  table_->resizeColumnToContents(0);
}

void PropertiesPanel::showRows(const QString& title, const std::vector<PropertyRow>& rows) {
  title_->setText("<b>" + title.toHtmlEscaped() + "</b>");
  table_->setRowCount(static_cast<int>(rows.size()));
  for (int i = 0; i < static_cast<int>(rows.size()); ++i) {
    table_->setItem(i, 0, new QTableWidgetItem(rows[i].first));
    table_->setItem(i, 1, new QTableWidgetItem(rows[i].second));
  }
  table_->resizeColumnToContents(0);
}

std::vector<PropertyRow> PropertiesPanel::rows() const {
  std::vector<PropertyRow> out;
  for (int i = 0; i < table_->rowCount(); ++i)
    out.emplace_back(table_->item(i, 0)->text(), table_->item(i, 1)->text());
  return out;
}

}  // namespace plumb::ui
