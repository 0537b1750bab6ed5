#include "ui/actions/remove_layer_reaction.hpp"

#include "ui/app_context.hpp"
#include "ui/layers/scene.hpp"
#include "ui/panels/layer_tree_panel.hpp"

namespace plumb::ui {

void RemoveLayerReaction::onTriggered() {
  Layer* layer = app().layers.currentLayer();
  while (layer && layer->parent()) layer = layer->parent();
  if (layer) app().scene.removeLayer(layer);
}

}  // namespace plumb::ui
