#include "ui/actions/colour_by_dataset_reaction.hpp"

#include "ui/app_context.hpp"
#include "ui/layers/dataset_layer.hpp"
#include "ui/layers/scene.hpp"
#include "ui/panels/layer_tree_panel.hpp"
#include "ui/panels/properties_panel.hpp"

namespace plumb::ui {

ColourByDatasetReaction::ColourByDatasetReaction(QAction* action, AppContext& app) : Reaction(action, app) {
  action->setShortcut(Qt::Key_D);
  action->setToolTip(tr("Each dataset (file, station) in its own colour, named in the view's legend"));
}

void ColourByDatasetReaction::onTriggered() {
  for (const auto& layer : app().scene.layers()) {
    if (layer->kind() != LayerKind::Dataset) continue;
    auto& dataset = static_cast<DatasetLayer&>(*layer);
    PointStyle style = dataset.style();
    style.mode = PointColorMode::Dataset;
    app().scene.requestStyle(dataset, style);
  }
  app().properties.showLayer(app().layers.currentLayer());  // its style editor and legend follow
}

}  // namespace plumb::ui
