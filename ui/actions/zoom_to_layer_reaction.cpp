#include "ui/actions/zoom_to_layer_reaction.hpp"

#include "ui/app_context.hpp"
#include "ui/layers/scene.hpp"
#include "ui/panels/layer_tree_panel.hpp"
#include "ui/view/scene_framing.hpp"
#include "ui/view/vtk_view_widget.hpp"

namespace plumb::ui {

void ZoomToLayerReaction::onTriggered() {
  if (const Layer* layer = app().layers.currentLayer()) frameLayer(app().scene, app().view, *layer);
  else frameVisible(app().scene, app().view);
}

}  // namespace plumb::ui
