#include "ui/tasks/task_manager.hpp"

#include <algorithm>

namespace plumb::ui {

TaskManager::TaskManager(QObject* parent) : QObject(parent) {}

Task* TaskManager::run(const QString& title, Task::Work work) {
  auto* task = new Task(title, std::move(work), this);
  tasks_.push_back(task);
  connect(task, &Task::finished, this, [this, task](bool ok, const QString& message) {
    tasks_.erase(std::remove(tasks_.begin(), tasks_.end(), task), tasks_.end());
    emit taskFinished(task->title(), ok, message);
    task->deleteLater();
    if (tasks_.empty()) emit idle();
  });
  emit taskStarted(task);
  task->start();
  return task;
}

void TaskManager::cancelAll() {
  for (Task* t : tasks_) t->cancel();
}

}  // namespace plumb::ui
