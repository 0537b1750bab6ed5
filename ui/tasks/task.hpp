#pragma once
// A long operation run off the UI thread (QGIS-style task): the work function runs on the
// TaskManager's thread pool (never Qt's global pool, see task_manager.hpp) with a
// plumb::Progress it reports to and checks for cancellation; it returns a continuation that
// is applied on the UI thread (e.g. adding the loaded layer). Progress is polled from the UI
// thread, so the worker never touches widgets and nothing pumps events.
#include <QFutureWatcher>
#include <QObject>
#include <QString>
#include <QTimer>

#include <functional>

#include "common/progress.hpp"

class QThreadPool;

namespace plumb::ui {

class Task : public QObject {
  Q_OBJECT
 public:
  /// Runs on a worker thread; returns what to do on the UI thread with the result.
  using Apply = std::function<void()>;
  using Work = std::function<Apply(Progress& progress)>;

  Task(QString title, Work work, QObject* parent = nullptr);
  ~Task() override;

  const QString& title() const { return title_; }
  /// Runs the work on `pool`.
  void start(QThreadPool& pool);
  void cancel();
  bool isRunning() const;
  double fraction() const { return progress_.fraction(); }
  QString stage() const { return QString::fromStdString(progress_.stage()); }
  /// Blocks until the work has finished (used by headless runs; never in UI handlers).
  void waitForFinished();

 signals:
  void progressed(double fraction, QString stage);
  /// After the continuation ran (ok) or the work threw (error message; "cancelled").
  void finished(bool ok, QString message);

 private:
  void onWorkDone();
  QString title_;
  Work work_;
  Progress progress_;
  QFutureWatcher<void> watcher_;
  QTimer poll_;
  Apply apply_;
  QString error_;
};

}  // namespace plumb::ui
