#include "ui/actions/inspection_reactions.hpp"

#include <vtkCamera.h>
#include <vtkRenderer.h>

#include "ui/app_context.hpp"
#include "ui/layers/dataset_layer.hpp"
#include "ui/panels/layer_tree_panel.hpp"
#include "ui/panels/log_panel.hpp"
#include "ui/registration/registration_panel.hpp"
#include "ui/layers/scene.hpp"
#include "ui/inspection/measure_tool.hpp"
#include "ui/registration/manual_align_panel.hpp"
#include "ui/view/scene_framing.hpp"
#include "ui/view/vtk_view_widget.hpp"

namespace plumb::ui {

MeasureReaction::MeasureReaction(QAction* action, AppContext& app) : Reaction(action, app) {
  action->setCheckable(true);
  action->setShortcut(Qt::Key_M);
  action->setToolTip(tr("Click a point for its coordinates, a second one for the distance"));
}

void MeasureReaction::onTriggered() {
  const bool on = action()->isChecked();
  if (on && app().manual) app().manual->setPicking(false);
  app().measure->setActive(on);
}

ProjectionReaction::ProjectionReaction(QAction* action, AppContext& app) : Reaction(action, app) {
  action->setCheckable(true);
  action->setShortcut(Qt::Key_O);
}

void ProjectionReaction::onTriggered() {
  app().view.renderer()->GetActiveCamera()->SetParallelProjection(action()->isChecked());
  // Refit along the current direction (the parallel scale from the data's robust extent).
  if (!frameVisible(app().scene, app().view)) app().view.requestRender();
}

BlinkReaction::BlinkReaction(QAction* action, AppContext& app) : Reaction(action, app) {
  action->setCheckable(true);
  action->setShortcut(Qt::Key_B);
  timer_.setInterval(kPeriodMs);
  connect(&timer_, &QTimer::timeout, this, &BlinkReaction::tick);
}

void BlinkReaction::onTriggered() {
  if (!action()->isChecked()) return stop();
  Layer* layer = app().registration ? app().registration->sourceLayer() : nullptr;
  if (!layer || layer->kind() != LayerKind::Dataset) layer = app().layers.currentRootLayer();
  if (!layer || layer->kind() != LayerKind::Dataset) {
    app().log.error(tr("Blink: choose a registration source or select a dataset"));
    action()->setChecked(false);
    return;
  }
  layer_ = LayerRef(*layer);
  timer_.start();
}

void BlinkReaction::tick() {
  auto* layer = static_cast<DatasetLayer*>(layer_.get());
  if (!layer) {  // removed while blinking
    timer_.stop();
    action()->setChecked(false);
    return;
  }
  layer->setShowsTransform(!layer->showsTransform());
  app().scene.layerChanged(layer);
}

void BlinkReaction::stop() {
  timer_.stop();
  if (auto* layer = static_cast<DatasetLayer*>(layer_.get()); layer && !layer->showsTransform()) {
    layer->setShowsTransform(true);
    app().scene.layerChanged(layer);
  }
  layer_ = LayerRef();
}

}  // namespace plumb::ui
