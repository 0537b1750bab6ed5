#include "ui/tasks/task_manager.hpp"

#include <QThread>

#include <algorithm>

namespace plumb::ui {

TaskManager::TaskManager(QObject* parent) : QObject(parent) {
  pool_.setMaxThreadCount(QThread::idealThreadCount());
}

TaskManager::~TaskManager() {
  // The tasks (children, deleted after this body) hold their workers: stop them first.
  cancelAll();
  pool_.waitForDone();
}

Task* TaskManager::run(const QString& title, Task::Work work, std::vector<LayerRef> holds) {
  auto* task = new Task(title, std::move(work), this);
  tasks_.push_back(task);
  for (LayerRef& l : holds) held_.emplace_back(task, std::move(l));
  connect(task, &Task::finished, this, [this, task](bool ok, const QString& message) {
    tasks_.erase(std::remove(tasks_.begin(), tasks_.end(), task), tasks_.end());
    std::erase_if(held_, [task](const auto& h) { return h.first == task; });
    emit taskFinished(task->title(), ok, message);
    task->deleteLater();
    if (tasks_.empty()) emit idle();
  });
  emit taskStarted(task);
  task->start(pool_);
  return task;
}

bool TaskManager::holds(const Layer* layer) const {
  return std::any_of(held_.begin(), held_.end(), [layer](const auto& h) { return h.second.is(layer); });
}

bool TaskManager::holdsLayers() const {
  return std::any_of(held_.begin(), held_.end(), [](const auto& h) { return h.second.get() != nullptr; });
}

void TaskManager::cancelAll() {
  for (Task* t : tasks_) t->cancel();
}

}  // namespace plumb::ui
