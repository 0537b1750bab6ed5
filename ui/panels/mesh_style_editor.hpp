#pragma once
// Editor of a model's mesh style: edges and transparency.
#include <QWidget>

class QCheckBox;
class QSlider;

namespace plumb::ui {

class ModelLayer;
class Scene;

class MeshStyleEditor : public QWidget {
  Q_OBJECT
 public:
  explicit MeshStyleEditor(Scene& scene, QWidget* parent = nullptr);
  void setLayer(ModelLayer* layer);

 private:
  void apply();
  Scene& scene_;
  ModelLayer* layer_ = nullptr;
  QCheckBox* edges_;
  QSlider* opacity_;
  bool loading_ = false;
};

}  // namespace plumb::ui
