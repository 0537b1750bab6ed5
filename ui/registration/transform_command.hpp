#pragma once
// An applied transform on the undo stack (Edit > Undo/Redo): registration results, manual
// alignments, reverts. Edit > Remove layer keeps removed layers alive in its own command, so
// the history stays valid; a layer destroyed otherwise (scene API) makes its commands no-ops
// that the stack drops (obsolete).
#include <QUndoCommand>

#include "model/rigid_transform.hpp"
#include "ui/layers/layer.hpp"

namespace plumb::ui {

class Layer;
class Scene;

class TransformCommand : public QUndoCommand {
 public:
  TransformCommand(Scene& scene, Layer& layer, const RigidTransform& before,
                   const RigidTransform& after, const QString& text);
  void undo() override;
  void redo() override;

 private:
  Scene& scene_;
  LayerRef layer_;
  RigidTransform before_, after_;
};

}  // namespace plumb::ui
