#include "ui/screenshot_run.hpp"

#include <QCoreApplication>
#include <QTimer>

#include <iostream>

#include "ui/layers/scene.hpp"
#include "ui/main_window.hpp"
#include "ui/panels/log_panel.hpp"
#include "ui/tasks/task_manager.hpp"
#include "ui/view/screenshot.hpp"
#include "ui/view/standard_view.hpp"
#include "ui/view/vtk_view_widget.hpp"

namespace plumb::ui {

ScreenshotRun::ScreenshotRun(MainWindow& window, QString output, QObject* parent)
    : QObject(parent), window_(window), output_(std::move(output)) {
  connect(&window_.context().log, &LogPanel::logged, this,
          [](LogLevel level, const QString& message) {
            if (level == LogLevel::Error) std::cerr << "plumb: error: " << message.toStdString() << "\n";
          });
}

void ScreenshotRun::start(const QStringList& files) {
  if (files.isEmpty()) {
    QTimer::singleShot(0, this, &ScreenshotRun::finish);
    return;
  }
  connect(&window_.context().tasks, &TaskManager::idle, this, &ScreenshotRun::finish,
          Qt::QueuedConnection);
  window_.openFiles(files);
}

void ScreenshotRun::finish() {
  AppContext& app = window_.context();
  resetCamera(app.view.renderer());
  int code = app.log.errorCount() > 0 ? 1 : 0;
  try {
    saveScreenshot(app.view, output_);
  } catch (const std::exception& e) {
    std::cerr << "plumb: error: " << e.what() << "\n";
    code = 1;
  }
  QCoreApplication::exit(code);
}

}  // namespace plumb::ui
