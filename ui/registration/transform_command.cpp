#include "ui/registration/transform_command.hpp"

#include "ui/layers/layer_transform.hpp"

namespace plumb::ui {

TransformCommand::TransformCommand(Scene& scene, Layer& layer, const RigidTransform& before,
                                   const RigidTransform& after, const QString& text)
    : QUndoCommand(text), scene_(scene), layer_(layer), before_(before), after_(after) {}

void TransformCommand::undo() {
  if (Layer* layer = layer_.get()) setLayerTransform(scene_, *layer, before_);
  else setObsolete(true);
}
void TransformCommand::redo() {
  if (Layer* layer = layer_.get()) setLayerTransform(scene_, *layer, after_);
  else setObsolete(true);
}

}  // namespace plumb::ui
