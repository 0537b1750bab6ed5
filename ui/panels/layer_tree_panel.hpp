#pragma once
// The layer tree dock: one row per layer (datasets with their scans, models, features,
// results), a check box per row for show/hide.
#include <QTreeWidget>

namespace plumb::ui {

class Layer;
class Scene;

class LayerTreePanel : public QTreeWidget {
  Q_OBJECT
 public:
  explicit LayerTreePanel(Scene& scene, QWidget* parent = nullptr);

  Layer* currentLayer() const;
  /// The top-level layer (dataset, model) of the current one, or nullptr.
  Layer* currentRootLayer() const;
  void setCurrentLayer(const Layer* layer);
  /// The row of a layer (nullptr if absent); for tests.
  QTreeWidgetItem* itemOf(const Layer* layer) const;

 signals:
  void currentLayerChanged(plumb::ui::Layer* layer);

 private:
  void rebuild();
  void addItems(Layer& layer, QTreeWidgetItem* parent);
  Scene& scene_;
  bool rebuilding_ = false;
};

/// The Layer a tree item stands for (nullptr for none).
Layer* layerOf(const QTreeWidgetItem* item);

}  // namespace plumb::ui
