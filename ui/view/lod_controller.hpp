#pragma once
// Level of detail: layers draw their reduced representation while the camera moves and the
// full one once the camera has been still for a short while.
#include <QObject>
#include <QTimer>

namespace plumb::ui {

class Scene;
class VtkViewWidget;

class LodController : public QObject {
  Q_OBJECT
 public:
  /// Full detail returns after the camera has been still this long.
  static constexpr int kSettleMs = 250;
  LodController(VtkViewWidget& view, Scene& scene, QObject* parent = nullptr);

 private:
  VtkViewWidget& view_;
  Scene& scene_;
  QTimer settle_;
};

}  // namespace plumb::ui
