#include "ui/actions/inspection_reactions.hpp"

#include <vtkCamera.h>
#include <vtkRenderer.h>

#include "ui/app_context.hpp"
#include "ui/layers/scene.hpp"
#include "ui/inspection/measure_tool.hpp"
#include "ui/registration/manual_align_panel.hpp"
#include "ui/view/standard_view.hpp"
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
  vtkRenderer* renderer = app().view.renderer();
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetParallelProjection(action()->isChecked());
  // Refit along the current direction (the parallel scale from the data's robust extent).
  const Bounds world = app().scene.visibleFramingBounds();
  if (!world.empty()) {
    double b[6];
    app().scene.renderBounds(world, b);
    zoomToBounds(renderer, b);
  }
  app().view.requestRender();
}

}  // namespace plumb::ui
