#include "ui/actions/reaction.hpp"

#include "ui/app_context.hpp"
#include "ui/tasks/task_manager.hpp"

namespace plumb::ui {

Reaction::Reaction(QAction* action, AppContext& app) : QObject(action), action_(action), app_(app) {
  connect(action, &QAction::triggered, this, [this] {
    if (canRun()) onTriggered();
  });
}

void Reaction::updateEnableState() { action_->setEnabled(canRun()); }

void Reaction::followTasks() {
  connect(&app_.tasks, &TaskManager::taskStarted, this, &Reaction::updateEnableState);
  connect(&app_.tasks, &TaskManager::taskFinished, this, &Reaction::updateEnableState);
  updateEnableState();
}

}  // namespace plumb::ui
