// File handling a surveyor relies on (issue 17, "Files"): each file dialog starts in the last
// folder chosen for its kind of file; the registered-cloud export proposes a derived name, never
// the input's own, and refuses to write over its input; closing with applied transforms not
// saved asks Save / Discard / Cancel.
#include <QAction>
#include <QApplication>
#include <QFile>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QTest>
#include <QTimer>
#include <QUndoStack>

#include "gui/grid_ply.hpp"
#include "gui/menu_actions.hpp"
#include "gui/open_window.hpp"
#include "support/test_support.hpp"
#include "ui/actions/file_dialogs.hpp"
#include "ui/layers/scene.hpp"
#include "ui/main_window.hpp"
#include "ui/panels/layer_tree_panel.hpp"
#include "ui/panels/log_panel.hpp"
#include "ui/tasks/task_manager.hpp"

using namespace plumb;
using namespace plumb::ui;

namespace {
QString q(const std::filesystem::path& p) { return QString::fromStdString(p.string()); }

struct Request {
  FileRequest kind;
  QString suggested;
};
}  // namespace

class GuiFilesTest : public QObject {
  Q_OBJECT

 private slots:
  void init() {
    QSettings().remove("folders");  // nothing remembered from earlier runs
    test::showMainWindow(window_, QSize(1000, 700));
    if (QTest::currentTestFailed()) return;
    requests_.clear();
    chosen_.clear();
    setFileChooser([this](FileRequest kind, const QString&, const QString& suggested, const QString&) {
      requests_.push_back({kind, suggested});
      return chosen_;
    });
  }
  void cleanup() {
    setFileChooser({});
    window_.reset();
  }

  void dialogsRememberTheFolderOfEachKindAndExportsProposeDerivedNames() {
    AppContext& app = window_->context();
    const auto data_dir = test::scratchDir("gui_files_data");
    const auto out_dir = test::scratchDir("gui_files_out");
    const QString scan = q(test::writeGridPly(data_dir / "station_7.ply", 21, 200, 0, 0));

    // File > Open: nothing remembered yet, so no start folder.
    chosen_ = {scan};
    QSignalSpy idle(&app.tasks, &TaskManager::idle);
    test::menuAction(*window_, "File", "Open...")->trigger();
    QVERIFY(idle.wait(30000));
    QCOMPARE(requests_.back().kind, FileRequest::OpenFiles);
    QVERIFY(requests_.back().suggested.isEmpty());
    QCOMPARE(app.scene.layers().size(), std::size_t{1});
    app.layers.setCurrentLayer(app.scene.layers()[0].get());

    // Export registered cloud: "<input>_registered.e57" next to the input (no export folder yet).
    chosen_ = {};
    test::menuAction(*window_, "File", "Export registered cloud...")->trigger();
    QCOMPARE(requests_.back().kind, FileRequest::SaveFile);
    QCOMPARE(requests_.back().suggested, q(data_dir / "station_7_registered.e57"));

    // Choosing the input itself is refused, and the input is untouched.
    const QByteArray before = readAll(scan);
    chosen_ = {scan};
    const int errors = app.log.errorCount();
    test::menuAction(*window_, "File", "Export registered cloud...")->trigger();
    if (app.tasks.runningCount() > 0) QVERIFY(idle.wait(30000));
    QCOMPARE(app.log.errorCount(), errors + 1);
    QVERIFY(app.log.toPlainText().contains("station_7.ply"));
    QCOMPARE(readAll(scan), before);

    // A screenshot exported to another folder makes it the export folder ...
    chosen_ = {q(out_dir / "view.png")};
    test::menuAction(*window_, "File", "Export screenshot...")->trigger();
    QVERIFY(QFile::exists(q(out_dir / "view.png")));
    chosen_ = {};
    test::menuAction(*window_, "File", "Export registered cloud...")->trigger();
    QCOMPARE(requests_.back().suggested, q(out_dir / "station_7_registered.e57"));
    test::menuAction(*window_, "File", "Export transform...")->trigger();
    QCOMPARE(requests_.back().suggested, q(out_dir / "station_7_transform.json"));
    // ... while File > Open starts where the data was read.
    test::menuAction(*window_, "File", "Open...")->trigger();
    QCOMPARE(requests_.back().suggested, q(data_dir));
    // A new window (a new session) remembers both.
    window_ = std::make_unique<MainWindow>();
    test::menuAction(*window_, "File", "Open...")->trigger();
    QCOMPARE(requests_.back().suggested, q(data_dir));
    test::menuAction(*window_, "File", "Export screenshot...")->trigger();
    QCOMPARE(requests_.back().suggested, q(out_dir / "plumb.png"));
  }

  void closingWithAppliedTransformsAsksToSave() {
    AppContext& app = window_->context();
    const auto dir = test::scratchDir("gui_files_close");
    QSignalSpy idle(&app.tasks, &TaskManager::idle);
    window_->openFiles({q(test::writeGridPly(dir / "scan.ply", 11, 0, 0, 200))});
    QVERIFY(idle.wait(30000));
    // Loading files leaves nothing unsaved: the window closes without asking.
    QVERIFY(window_->close());
    QVERIFY(!answered_);
    window_->show();

    app.undo.push(new QUndoCommand("Apply registration"));  // what an applied transform leaves
    answerNextMessageBox(QMessageBox::Cancel);
    QVERIFY(!window_->close());
    QVERIFY(answered_);
    QVERIFY(window_->isVisible());

    // Save: the project is written, then the window closes.
    const QString project = q(dir / "site.plumb.json");
    QFile::remove(project);
    chosen_ = {project};
    answerNextMessageBox(QMessageBox::Save);
    QVERIFY(window_->close());
    QVERIFY(QFile::exists(project));
    QVERIFY(app.undo.isClean());

    // Discard: closes without writing.
    window_->show();
    app.undo.push(new QUndoCommand("Apply registration"));
    QFile::remove(project);
    answerNextMessageBox(QMessageBox::Discard);
    QVERIFY(window_->close());
    QVERIFY(!QFile::exists(project));
  }

 private:
  static QByteArray readAll(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
  }
  /// Clicks `button` of the "unsavedChanges" box once it is shown (it runs its own event loop).
  void answerNextMessageBox(QMessageBox::StandardButton button) {
    answered_ = false;
    QTimer::singleShot(0, this, [this, button] {
      auto* box = window_->findChild<QMessageBox*>("unsavedChanges");
      if (!box) return;
      answered_ = true;
      box->button(button)->click();
    });
  }
  std::unique_ptr<MainWindow> window_;
  QStringList chosen_;
  std::vector<Request> requests_;
  bool answered_ = false;
};

int main(int argc, char** argv) { return test::runGuiTest<GuiFilesTest>(argc, argv, "PlumbTestsFiles"); }

#include "test_gui_files.moc"
