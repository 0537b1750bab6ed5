#include "ui/registration/transform_command.hpp"

#include "ui/layers/layer_transform.hpp"

namespace plumb::ui {

TransformCommand::TransformCommand(Scene& scene, Layer& layer, const RigidTransform& before,
                                   const RigidTransform& after, const QString& text)
    : QUndoCommand(text), scene_(scene), layer_(layer), before_(before), after_(after) {}

void TransformCommand::undo() { setLayerTransform(scene_, layer_, before_); }
void TransformCommand::redo() { setLayerTransform(scene_, layer_, after_); }

}  // namespace plumb::ui
