#include "ui/tasks/task.hpp"

#include <QThreadPool>
#include <QtConcurrent/QtConcurrentRun>

#include "common/error.hpp"

namespace plumb::ui {

namespace {
constexpr int kPollIntervalMs = 100;
}

Task::Task(QString title, Work work, QObject* parent)
    : QObject(parent), title_(std::move(title)), work_(std::move(work)) {
  poll_.setInterval(kPollIntervalMs);
  connect(&poll_, &QTimer::timeout, this, [this] { emit progressed(fraction(), stage()); });
  connect(&watcher_, &QFutureWatcher<void>::finished, this, &Task::onWorkDone);
}

Task::~Task() {
  // A task deleted while running: stop its work and wait, the worker holds `this`.
  if (isRunning()) {
    progress_.cancel();
    watcher_.waitForFinished();
  }
}

void Task::start(QThreadPool& pool) {
  poll_.start();
  watcher_.setFuture(QtConcurrent::run(&pool, [this] {
    try {
      apply_ = work_(progress_);
    } catch (const Canceled&) {
      error_ = "cancelled";
    } catch (const std::exception& e) {
      error_ = QString::fromUtf8(e.what());
    } catch (...) {
      error_ = "unknown error";
    }
  }));
}

void Task::cancel() { progress_.cancel(); }

bool Task::isRunning() const { return watcher_.isRunning(); }

void Task::waitForFinished() { watcher_.waitForFinished(); }

void Task::onWorkDone() {
  poll_.stop();
  if (!error_.isEmpty()) {
    emit finished(false, error_);
    return;
  }
  try {
    if (apply_) apply_();
  } catch (const std::exception& e) {
    emit finished(false, QString::fromUtf8(e.what()));
    return;
  }
  emit progressed(1.0, stage());
  emit finished(true, {});
}

}  // namespace plumb::ui
