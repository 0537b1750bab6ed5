#pragma once
// The start of the GUI tests: a shown main window, optionally with some files opened the way
// File > Open does (MainWindow::openFiles: background loading tasks), loaded without errors;
// and the test's main().
#include <QApplication>
#include <QSignalSpy>
#include <QSize>
#include <QStringList>
#include <QTest>

#include <memory>

#include "ui/main_window.hpp"
#include "ui/panels/log_panel.hpp"
#include "ui/tasks/task_manager.hpp"
#include "ui/view/surface_format.hpp"

namespace plumb::test {

/// Makes `window` of `size` and shows it; fails the current test (check
/// QTest::currentTestFailed()) if the window is not exposed.
inline void showMainWindow(std::unique_ptr<ui::MainWindow>& window, QSize size) {
  window = std::make_unique<ui::MainWindow>();
  window->resize(size);
  window->show();
  QVERIFY(QTest::qWaitForWindowExposed(window.get()));
}

/// showMainWindow (1400 x 900), then opens `files`; fails the current test (check
/// QTest::currentTestFailed()) if the window is not exposed, loading takes over 60 s or logs an
/// error.
inline void openWindowWithFiles(std::unique_ptr<ui::MainWindow>& window, const QStringList& files) {
  showMainWindow(window, QSize(1400, 900));
  if (QTest::currentTestFailed()) return;
  ui::AppContext& app = window->context();
  QSignalSpy idle(&app.tasks, &ui::TaskManager::idle);
  window->openFiles(files);
  QVERIFY(idle.wait(60000));
  QVERIFY2(app.log.errorCount() == 0, qPrintable(app.log.toPlainText()));
}

/// The main() of a GUI test: the default surface format (before the application), the
/// application with its settings under `organization`, then the slots of `Test`.
template <class Test>
int runGuiTest(int argc, char** argv, const char* organization = "PlumbTests") {
  ui::setDefaultSurfaceFormat();
  QApplication app(argc, argv);
  QCoreApplication::setOrganizationName(organization);
  Test test;
  return QTest::qExec(&test, argc, argv);
}

}  // namespace plumb::test
