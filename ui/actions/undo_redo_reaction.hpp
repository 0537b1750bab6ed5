#pragma once
#include "ui/actions/reaction.hpp"

namespace plumb::ui {

/// Edit > Undo / Redo: steps through the undo stack, named after the step ("Undo Remove
/// scan.ply"). Disabled when there is no such step, and while a running task holds layers:
/// undoing or redoing a removal or a transform then could take away or move a layer whose
/// result the task is about to apply.
class UndoRedoReaction : public Reaction {
  Q_OBJECT
 public:
  enum class Step { Undo, Redo };
  UndoRedoReaction(QAction* action, AppContext& app, Step step);

 protected:
  void onTriggered() override;
  bool canRun() const override;

 private:
  void updateText();
  Step step_;
};

}  // namespace plumb::ui
