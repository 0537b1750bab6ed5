#pragma once
// An applied transform on the undo stack (Edit > Undo/Redo): registration results, manual
// alignments, reverts. The layer is looked up by pointer; the main window clears the stack
// when a layer is removed, so commands never outlive their layer.
#include <QUndoCommand>

#include "model/rigid_transform.hpp"

namespace plumb::ui {

class Layer;
class Scene;

class TransformCommand : public QUndoCommand {
 public:
  TransformCommand(Scene& scene, Layer& layer, const RigidTransform& before,
                   const RigidTransform& after, const QString& text);
  void undo() override;
  void redo() override;
  Layer& layer() const { return layer_; }

 private:
  Scene& scene_;
  Layer& layer_;
  RigidTransform before_, after_;
};

}  // namespace plumb::ui
