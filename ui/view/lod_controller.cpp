#include "ui/view/lod_controller.hpp"

#include "ui/layers/scene.hpp"
#include "ui/view/vtk_view_widget.hpp"

namespace plumb::ui {

LodController::LodController(VtkViewWidget& view, Scene& scene, QObject* parent)
    : QObject(parent), view_(view), scene_(scene) {
  settle_.setSingleShot(true);
  settle_.setInterval(kSettleMs);
  connect(&view_, &VtkViewWidget::interactionStarted, this, [this] {
    settle_.stop();
    if (!scene_.reducedDetail()) scene_.setReducedDetail(true);
  });
  connect(&view_, &VtkViewWidget::interactionEnded, this, [this] { settle_.start(); });
  connect(&settle_, &QTimer::timeout, this, [this] {
    scene_.setReducedDetail(false);
    view_.requestRender();
  });
}

}  // namespace plumb::ui
