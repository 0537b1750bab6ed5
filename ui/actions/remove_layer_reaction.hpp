#pragma once
#include "ui/actions/reaction.hpp"

namespace plumb::ui {

class Layer;

/// Edit > Remove layer: removes the current root layer, undoably (RemoveLayerCommand: the rest
/// of the history stays). Disabled when there is none or while a running task holds it (its
/// result goes to that layer).
class RemoveLayerReaction : public Reaction {
  Q_OBJECT
 public:
  RemoveLayerReaction(QAction* action, AppContext& app);

 protected:
  void onTriggered() override;
  bool canRun() const override;
};

}  // namespace plumb::ui
