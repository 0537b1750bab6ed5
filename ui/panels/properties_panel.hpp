#pragma once
// The properties dock: facts about the current layer (or the picked feature) and the style
// editor that fits the layer.
#include <QWidget>

#include <vector>

#include "ui/layers/layer.hpp"

class QTableWidget;
class QLabel;

namespace plumb::ui {

class MeshStyleEditor;
class PointStyleEditor;
class Scene;

class PropertiesPanel : public QWidget {
  Q_OBJECT
 public:
  explicit PropertiesPanel(Scene& scene, QWidget* parent = nullptr);
  void showLayer(Layer* layer);
  /// Shows rows about something picked in the view (a feature).
  void showRows(const QString& title, const std::vector<PropertyRow>& rows);
  /// Current rows, for tests.
  std::vector<PropertyRow> rows() const;

 private:
  /// One row per legend entry: a colour swatch and its meaning, the colour as #rrggbb.
  void appendLegend(const std::vector<LegendEntry>& legend);
  LayerRef current_;  ///< the layer shown
  QLabel* title_;
  QTableWidget* table_;
  PointStyleEditor* points_;
  MeshStyleEditor* mesh_;
};

}  // namespace plumb::ui
