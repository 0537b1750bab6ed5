#include "ui/actions/remove_layer_reaction.hpp"

#include <QUndoStack>

#include "ui/actions/remove_layer_command.hpp"
#include "ui/app_context.hpp"
#include "ui/layers/scene.hpp"
#include "ui/panels/layer_tree_panel.hpp"
#include "ui/tasks/task_manager.hpp"

namespace plumb::ui {

RemoveLayerReaction::RemoveLayerReaction(QAction* action, AppContext& app) : Reaction(action, app) {
  connect(&app.layers, &LayerTreePanel::currentLayerChanged, this, &Reaction::updateEnableState);
  connect(&app.scene, &Scene::layersChanged, this, &Reaction::updateEnableState);
  followTasks();
}

bool RemoveLayerReaction::canRun() const {
  const Layer* layer = app().layers.currentRootLayer();
  return layer && !app().tasks.holds(layer);
}

void RemoveLayerReaction::onTriggered() {
  if (Layer* layer = app().layers.currentRootLayer()) app().undo.push(new RemoveLayerCommand(app().scene, *layer));
}

}  // namespace plumb::ui
