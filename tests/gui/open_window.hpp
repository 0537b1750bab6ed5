#pragma once
// The start of most workflow GUI tests: a shown main window with some files opened the way
// File > Open does (MainWindow::openFiles: background loading tasks), loaded without errors.
#include <QSignalSpy>
#include <QStringList>
#include <QTest>

#include <memory>

#include "ui/main_window.hpp"
#include "ui/panels/log_panel.hpp"
#include "ui/tasks/task_manager.hpp"

namespace plumb::test {

/// Makes `window` (1400 x 900), shows it and opens `files`; fails the current test (check
/// QTest::currentTestFailed()) if the window is not exposed, loading takes over 60 s or logs an
/// error.
inline void openWindowWithFiles(std::unique_ptr<ui::MainWindow>& window, const QStringList& files) {
  window = std::make_unique<ui::MainWindow>();
  window->resize(1400, 900);
  window->show();
  QVERIFY(QTest::qWaitForWindowExposed(window.get()));
  ui::AppContext& app = window->context();
  QSignalSpy idle(&app.tasks, &ui::TaskManager::idle);
  window->openFiles(files);
  QVERIFY(idle.wait(60000));
  QVERIFY2(app.log.errorCount() == 0, qPrintable(app.log.toPlainText()));
}

}  // namespace plumb::test
