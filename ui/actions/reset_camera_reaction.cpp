#include "ui/actions/reset_camera_reaction.hpp"

#include "ui/app_context.hpp"
#include "ui/view/scene_framing.hpp"
#include "ui/view/vtk_view_widget.hpp"

namespace plumb::ui {

void ResetCameraReaction::onTriggered() {
  frameScene(app().scene, app().view);
}

}  // namespace plumb::ui
