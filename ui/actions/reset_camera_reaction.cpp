#include "ui/actions/reset_camera_reaction.hpp"

#include "ui/app_context.hpp"
#include "ui/view/standard_view.hpp"
#include "ui/view/vtk_view_widget.hpp"

namespace plumb::ui {

void ResetCameraReaction::onTriggered() {
  resetCamera(app().view.renderer());
  app().view.requestRender();
}

}  // namespace plumb::ui
