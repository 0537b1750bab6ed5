#include "ui/panels/layer_tree_panel.hpp"

#include <QHeaderView>

#include "ui/layers/scene.hpp"

namespace plumb::ui {

namespace {
constexpr int kLayerRole = Qt::UserRole + 1;
}

Layer* layerOf(const QTreeWidgetItem* item) {
  return item ? static_cast<Layer*>(item->data(0, kLayerRole).value<void*>()) : nullptr;
}

LayerTreePanel::LayerTreePanel(Scene& scene, QWidget* parent)
    : QTreeWidget(parent), scene_(scene) {
  setObjectName("layerTree");
  setHeaderLabels({tr("Layer"), tr("Kind")});
  header()->setSectionResizeMode(0, QHeaderView::Stretch);
  header()->setStretchLastSection(false);
  connect(&scene_, &Scene::layersChanged, this, &LayerTreePanel::rebuild);
  connect(this, &QTreeWidget::itemChanged, this, [this](QTreeWidgetItem* item, int column) {
    Layer* layer = layerOf(item);
    if (rebuilding_ || column != 0 || !layer) return;
    const bool visible = item->checkState(0) == Qt::Checked;
    if (visible == layer->visible()) return;
    layer->setVisible(visible);
    scene_.layerChanged(layer);
  });
  connect(this, &QTreeWidget::currentItemChanged, this,
          [this](QTreeWidgetItem* current) {
            if (!rebuilding_) emit currentLayerChanged(layerOf(current));
          });
}

Layer* LayerTreePanel::currentLayer() const { return layerOf(currentItem()); }

Layer* LayerTreePanel::currentRootLayer() const {
  Layer* layer = currentLayer();
  while (layer && layer->parent()) layer = layer->parent();
  return layer;
}

QTreeWidgetItem* LayerTreePanel::itemOf(const Layer* layer) const {
  for (QTreeWidgetItemIterator it(const_cast<LayerTreePanel*>(this)); *it; ++it)
    if (layerOf(*it) == layer) return *it;
  return nullptr;
}

void LayerTreePanel::setCurrentLayer(const Layer* layer) {
  if (QTreeWidgetItem* item = itemOf(layer)) setCurrentItem(item);
}

void LayerTreePanel::rebuild() {
  Layer* current = currentLayer();
  rebuilding_ = true;
  clear();
  for (const auto& layer : scene_.layers()) addItems(*layer, nullptr);
  expandAll();
  rebuilding_ = false;
  if (QTreeWidgetItem* item = itemOf(current)) {
    setCurrentItem(item);
  } else {
    emit currentLayerChanged(nullptr);
  }
}

void LayerTreePanel::addItems(Layer& layer, QTreeWidgetItem* parent) {
  auto* item = parent ? new QTreeWidgetItem(parent) : new QTreeWidgetItem(this);
  item->setText(0, layer.name());
  item->setText(1, layerKindName(layer.kind()));
  item->setData(0, kLayerRole, QVariant::fromValue(static_cast<void*>(&layer)));
  item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
  item->setCheckState(0, layer.visible() ? Qt::Checked : Qt::Unchecked);
  for (const auto& c : layer.children()) addItems(*c, item);
}

}  // namespace plumb::ui
