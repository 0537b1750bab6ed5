// What guides a user who has not read the manual (issue 17): the empty window says how to
// start.
#include <QAction>
#include <QComboBox>
#include <QHash>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QSignalSpy>
#include <QStandardItemModel>
#include <QTest>

#include <cmath>

#include <vtkCamera.h>
#include <vtkRenderer.h>

#include "gui/menu_actions.hpp"
#include "gui/open_window.hpp"
#include "gui/room_scene.hpp"
#include "ui/actions/file_dialogs.hpp"
#include "ui/layers/dataset_layer.hpp"
#include "ui/layers/model_layer.hpp"
#include "ui/layers/scene.hpp"
#include "ui/panels/layer_tree_panel.hpp"
#include "ui/panels/log_panel.hpp"
#include "ui/registration/registration_panel.hpp"
#include "ui/tasks/task_manager.hpp"
#include "ui/view/vtk_view_widget.hpp"

using namespace plumb;
using namespace plumb::ui;

class GuiGuidanceTest : public QObject {
  Q_OBJECT

 private slots:
  void init() {
    test::showMainWindow(window_, QSize(1200, 800));
    setFileChooser([](FileRequest, const QString&, const QString&, const QString&) { return QStringList(); });
  }
  void cleanup() {
    setFileChooser({});
    if (window_)
      QVERIFY(QTest::qWaitFor([&] { return window_->context().tasks.runningCount() == 0; }, 120000));
    window_.reset();
  }

  // The hint shows in the empty view, goes with the first layer, comes back with none.
  void theEmptyViewSaysHowToStart() {
    AppContext& app = window_->context();
    auto* hint = app.view.findChild<QLabel*>("emptySceneHint");
    QVERIFY(hint);
    QVERIFY(hint->isVisible());
    QVERIFY(hint->text().contains("File &gt; Open (Ctrl+O)"));
    QVERIFY(hint->text().contains("F1"));
    QVERIFY(app.view.rect().contains(hint->geometry()));
    Layer* first = &app.scene.addDataset(test::roomScan(0.2, RigidTransform(), "a"));
    QVERIFY(!hint->isVisible());
    Layer* second = &app.scene.addModel(test::roomModel());
    app.scene.removeLayer(first);
    QVERIFY(!hint->isVisible());
    app.scene.removeLayer(second);
    QVERIFY(hint->isVisible());
    app.scene.addDataset(test::roomScan(0.2, RigidTransform(), "b"));
    app.scene.clear();
    QVERIFY(hint->isVisible());
  }

 private:
  std::unique_ptr<MainWindow> window_;
};

int main(int argc, char** argv) { return test::runGuiTest<GuiGuidanceTest>(argc, argv); }
#include "test_gui_guidance.moc"
