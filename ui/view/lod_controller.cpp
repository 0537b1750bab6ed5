#include "ui/view/lod_controller.hpp"

#include "ui/layers/scene.hpp"
#include "ui/view/vtk_view_widget.hpp"

namespace plumb::ui {

LodController::LodController(VtkViewWidget& view, Scene& scene, QObject* parent)
    : QObject(parent), view_(view), scene_(scene) {
  scene_.setLodBudget(budget_.points());
  settle_.setSingleShot(true);
  settle_.setInterval(kSettleMs);
  connect(&view_, &VtkViewWidget::interactionStarted, this, [this] {
    settle_.stop();
    moving_ = true;
    moving_frames_ = 0;
    view_.setFrameTiming(true);
    if (!scene_.reducedDetail()) {
      scene_.setReducedDetail(true);
      skip_frames_ = 1;
    }
  });
  connect(&view_, &VtkViewWidget::interactionEnded, this, [this] {
    moving_ = false;
    view_.setFrameTiming(false);
    // A click (no frame drawn while "moving") goes straight back to full detail: waiting for
    // the settle delay would draw one reduced frame and then one full frame for nothing.
    if (moving_frames_ == 0) {
      scene_.setReducedDetail(false);
      return;
    }
    settle_.start();
  });
  connect(&view_, &VtkViewWidget::frameRendered, this, &LodController::onFrame);
  connect(&settle_, &QTimer::timeout, this, [this] {
    scene_.setReducedDetail(false);
    view_.requestRender();
  });
}

void LodController::onFrame(double ms) {
  if (!moving_ || !scene_.reducedDetail()) return;
  ++moving_frames_;
  if (skip_frames_ > 0) {
    --skip_frames_;
    return;
  }
  if (budget_.addFrame(scene_.drawnPointCount(), ms)) {
    scene_.setLodBudget(budget_.points());
    skip_frames_ = 1;
  }
}

}  // namespace plumb::ui
