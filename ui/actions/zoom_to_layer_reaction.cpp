#include "ui/actions/zoom_to_layer_reaction.hpp"

#include "ui/app_context.hpp"
#include "ui/layers/scene.hpp"
#include "ui/panels/layer_tree_panel.hpp"
#include "ui/view/standard_view.hpp"
#include "ui/view/vtk_view_widget.hpp"

namespace plumb::ui {

void ZoomToLayerReaction::onTriggered() {
  const Layer* layer = app().layers.currentLayer();
  const Bounds world = layer ? layer->bounds() : app().scene.visibleBounds();
  if (world.empty()) return;
  double b[6];
  app().scene.renderBounds(world, b);
  zoomToBounds(app().view.renderer(), b);
  app().view.requestRender();
}

}  // namespace plumb::ui
