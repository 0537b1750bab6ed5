#include "ui/actions/undo_redo_reaction.hpp"

#include <QUndoStack>

#include "ui/app_context.hpp"
#include "ui/tasks/task_manager.hpp"

namespace plumb::ui {

UndoRedoReaction::UndoRedoReaction(QAction* action, AppContext& app, Step step)
    : Reaction(action, app), step_(step) {
  action->setShortcut(step == Step::Undo ? QKeySequence::Undo : QKeySequence::Redo);
  QUndoStack& stack = app.undo;
  const auto changed = step == Step::Undo ? &QUndoStack::canUndoChanged : &QUndoStack::canRedoChanged;
  const auto text = step == Step::Undo ? &QUndoStack::undoTextChanged : &QUndoStack::redoTextChanged;
  connect(&stack, changed, this, &Reaction::updateEnableState);
  connect(&stack, text, this, &UndoRedoReaction::updateText);
  connect(&stack, &QUndoStack::indexChanged, this, &Reaction::updateEnableState);
  updateText();
  followTasks();
}

bool UndoRedoReaction::canRun() const {
  const QUndoStack& stack = app().undo;
  const bool possible = step_ == Step::Undo ? stack.canUndo() : stack.canRedo();
  return possible && !app().tasks.holdsLayers();
}

void UndoRedoReaction::onTriggered() {
  if (step_ == Step::Undo) app().undo.undo();
  else app().undo.redo();
}

void UndoRedoReaction::updateText() {
  const QString step = step_ == Step::Undo ? app().undo.undoText() : app().undo.redoText();
  const QString verb = step_ == Step::Undo ? tr("&Undo") : tr("&Redo");
  action()->setText(step.isEmpty() ? verb : tr("%1 %2").arg(verb, step));
}

}  // namespace plumb::ui
