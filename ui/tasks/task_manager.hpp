#pragma once
// Runs Tasks, keeps them alive while they run, and tells when all are done.
#include <QObject>

#include <memory>
#include <vector>

#include "ui/tasks/task.hpp"

namespace plumb::ui {

class TaskManager : public QObject {
  Q_OBJECT
 public:
  explicit TaskManager(QObject* parent = nullptr);

  /// Starts a task (owned by the manager until it finishes).
  Task* run(const QString& title, Task::Work work);
  int runningCount() const { return static_cast<int>(tasks_.size()); }
  const std::vector<Task*>& running() const { return tasks_; }
  void cancelAll();

 signals:
  void taskStarted(plumb::ui::Task* task);
  void taskFinished(const QString& title, bool ok, const QString& message);
  /// The last running task finished.
  void idle();

 private:
  std::vector<Task*> tasks_;  ///< children of this object (Qt parent ownership)
};

}  // namespace plumb::ui
