#include "ui/actions/remove_layer_command.hpp"

#include <QObject>

#include "ui/layers/layer.hpp"
#include "ui/layers/scene.hpp"

namespace plumb::ui {

RemoveLayerCommand::RemoveLayerCommand(Scene& scene, Layer& layer)
    : QUndoCommand(QObject::tr("Remove %1").arg(layer.name())), scene_(scene), layer_(&layer) {}

RemoveLayerCommand::~RemoveLayerCommand() = default;

void RemoveLayerCommand::redo() {
  const auto& layers = scene_.layers();
  for (std::size_t i = 0; i < layers.size(); ++i)
    if (layers[i].get() == layer_) index_ = i;
  held_ = scene_.takeLayer(layer_);
}

void RemoveLayerCommand::undo() {
  if (held_) scene_.restoreLayer(std::move(held_), index_);
}

}  // namespace plumb::ui
