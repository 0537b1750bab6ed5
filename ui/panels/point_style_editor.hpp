#pragma once
// Editor of a dataset's point style: colour mode, scalar field, point size, and the
// before/after registration toggle.
#include <QWidget>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;

namespace plumb::ui {

class DatasetLayer;
class Scene;

class PointStyleEditor : public QWidget {
  Q_OBJECT
 public:
  explicit PointStyleEditor(Scene& scene, QWidget* parent = nullptr);
  void setLayer(DatasetLayer* layer);

 signals:
  /// A new style was requested (the legend may change).
  void styleApplied();

 private:
  void apply();
  void enableModes();
  Scene& scene_;
  DatasetLayer* layer_ = nullptr;
  QComboBox* mode_;
  QComboBox* field_;
  QDoubleSpinBox* size_;
  QCheckBox* registered_;
  bool loading_ = false;
};

}  // namespace plumb::ui
