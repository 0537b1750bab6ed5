#pragma once
// Runs Tasks, keeps them alive while they run, and tells when all are done. The tasks run on
// the manager's own thread pool (as many threads as cores), not on Qt's global pool: Qt's
// raster painting (progress bars, widgets) waits for jobs it puts on the global pool, so long
// loads filling it froze the window until one finished (four 256-million-point files opened
// together: the first view after 155 s instead of 5 s, session 18).
#include <QObject>
#include <QThreadPool>

#include <memory>
#include <vector>

#include "ui/layers/layer.hpp"
#include "ui/tasks/task.hpp"

namespace plumb::ui {

class TaskManager : public QObject {
  Q_OBJECT
 public:
  explicit TaskManager(QObject* parent = nullptr);
  ~TaskManager() override;

  /// Starts a task (owned by the manager until it finishes). `holds`: the layers whose result
  /// the task applies when it finishes (registration inputs...): actions that would remove or
  /// replace them stay disabled meanwhile (holds()).
  Task* run(const QString& title, Task::Work work, std::vector<LayerRef> holds = {});
  int runningCount() const { return static_cast<int>(tasks_.size()); }
  const std::vector<Task*>& running() const { return tasks_; }
  void cancelAll();
  /// A running task holds `layer` (a root layer) / any layer.
  bool holds(const Layer* layer) const;
  bool holdsLayers() const;

 signals:
  void taskStarted(plumb::ui::Task* task);
  void taskFinished(const QString& title, bool ok, const QString& message);
  /// The last running task finished.
  void idle();

 private:
  QThreadPool pool_;
  std::vector<Task*> tasks_;  ///< children of this object (Qt parent ownership)
  std::vector<std::pair<const Task*, LayerRef>> held_;
};

}  // namespace plumb::ui
