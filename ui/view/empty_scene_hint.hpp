#pragma once
// The getting-started hint over the 3D view while the scene has no layers: how to open scans,
// a model or a project, and where the guide is. Hidden once a layer exists, back when the last
// one is removed.
#include <QLabel>

namespace plumb::ui {

class Scene;

class EmptySceneHint : public QLabel {
  Q_OBJECT
 public:
  /// A child of `view`, centred on it.
  EmptySceneHint(Scene& scene, QWidget& view);

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  void follow();
  void centre();
  Scene& scene_;
  QWidget& view_;
};

}  // namespace plumb::ui
