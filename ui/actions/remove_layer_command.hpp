#pragma once
// Edit > Remove layer as an undo command: the removed root layer is kept (off the scene) by
// the command, so Undo puts it back where it was and the transforms applied to it before stay
// undoable; the rest of the history is untouched. The layer is destroyed with the command
// (undo stack cleared, e.g. by Open project).
#include <QUndoCommand>

#include <memory>

namespace plumb::ui {

class Layer;
class Scene;

class RemoveLayerCommand : public QUndoCommand {
 public:
  RemoveLayerCommand(Scene& scene, Layer& layer);
  ~RemoveLayerCommand() override;
  void redo() override;
  void undo() override;

 private:
  Scene& scene_;
  Layer* layer_;                  ///< in the scene while not removed; owned by held_ otherwise
  std::unique_ptr<Layer> held_;   ///< the removed layer
  std::size_t index_ = 0;         ///< its place among the scene's root layers
};

}  // namespace plumb::ui
