// What guides a user who has not read the manual (issue 17): the empty window says how to
// start, the common actions have keyboard shortcuts (none shared), and a colour mode the data
// cannot show is greyed out in the style editor and said in the log instead of silently
// replaced by elevation.
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

namespace {

/// Every action of the menu bar's menus and their submenus, with its menu path.
void collectActions(QMenu& menu, const QString& path, QList<std::pair<QString, QAction*>>& out) {
  for (QAction* a : menu.actions()) {
    if (a->menu()) collectActions(*a->menu(), path + " > " + test::plainLabel(a->text()), out);
    else if (!a->isSeparator()) out.append({path + " > " + test::plainLabel(a->text()), a});
  }
}

/// A room scan of two scans, the second one with RGB colours.
std::shared_ptr<const Dataset> halfColouredRoom() {
  auto data = std::make_shared<Dataset>(*test::roomScan(0.2, RigidTransform(), "mixed"));
  Scan coloured = data->scans.front();
  coloured.name = "coloured";
  coloured.cloud.colors.assign(coloured.cloud.size(), Rgb8{200, 40, 40});
  data->scans.front().name = "grey";
  data->scans.push_back(std::move(coloured));
  return data;
}

}  // namespace

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

  // No two actions share a key; the common ones have one.
  void shortcutsAreUniqueAndCoverTheCommonActions() {
    QList<std::pair<QString, QAction*>> actions;
    for (QAction* top : window_->menuBar()->actions())
      if (top->menu()) collectActions(*top->menu(), test::plainLabel(top->text()), actions);
    QVERIFY(actions.size() > 20);
    QHash<QString, QString> owner;  // key -> action
    for (const auto& [path, action] : actions)
      for (const QKeySequence& key : action->shortcuts()) {
        const QString text = key.toString(QKeySequence::PortableText);
        QVERIFY2(!owner.contains(text), qPrintable(text + " is " + owner.value(text) + " and " + path));
        owner.insert(text, path);
      }
    const std::pair<const char*, const char*> common[] = {
        {"File", "Open..."}, {"File", "Open project..."}, {"File", "Save project..."},
        {"File", "Export registered cloud..."}, {"File", "Export registration report..."},
        {"Registration", "Detect features"}, {"Registration", "Register"},
        {"Registration", "Accept result"}, {"Registration", "Revert result"},
        {"View", "Top"}, {"View", "Front"}, {"View", "Side"}, {"View", "Iso"},
        {"View", "Reset camera"}, {"View", "Zoom to layer"}, {"Help", "Getting started"}};
    for (const auto& [menu, label] : common) {
      QAction* a = test::menuAction(*window_, menu, label);
      QVERIFY2(a && !a->shortcut().isEmpty(), label);
    }
  }

  // Keys trigger their actions: Ctrl+1 looks down from the top, Ctrl+D detects features.
  void shortcutsTriggerTheirActions() {
    AppContext& app = window_->context();
    Layer* scan = &app.scene.addDataset(test::roomScan(0.1, test::scanOffset(), "scan"));
    Layer* reference = &app.scene.addDataset(test::roomScan(0.08, RigidTransform(), "reference"));
    app.registration->setSourceLayer(scan);
    app.registration->setTargetLayer(reference);
    window_->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(window_.get()));

    QAction* top = test::menuAction(*window_, "View", "Top");
    QSignalSpy top_spy(top, &QAction::triggered);
    QTest::keyClick(window_.get(), Qt::Key_1, Qt::ControlModifier);
    QCOMPARE(top_spy.count(), 1);
    double d[3];
    app.view.renderer()->GetActiveCamera()->GetDirectionOfProjection(d);
    QVERIFY2(d[2] < -0.99, qPrintable(QString::number(d[2])));

    QAction* front = test::menuAction(*window_, "View", "Front");
    QSignalSpy front_spy(front, &QAction::triggered);
    QTest::keyClick(window_.get(), Qt::Key_2, Qt::ControlModifier);
    QCOMPARE(front_spy.count(), 1);
    app.view.renderer()->GetActiveCamera()->GetDirectionOfProjection(d);
    QVERIFY(std::abs(d[2]) < 0.01);

    QSignalSpy detected(app.registration, &RegistrationPanel::featuresDetected);
    QTest::keyClick(window_.get(), Qt::Key_D, Qt::ControlModifier);
    QVERIFY(detected.wait(120000));
    QVERIFY2(detected.at(0).at(0).toBool(), qPrintable(app.log.toPlainText()));
    QCOMPARE(top_spy.count(), 1);  // nothing else fired
  }

  // RGB on a cloud without colours: greyed out with the reason; asked for anyway (a project,
  // a script), the log names the layer and what it lacks. A dataset with colours in some scans
  // only: RGB is offered, and the log names the scans drawn by elevation.
  void colourModesTheDataCannotShowAreSaid() {
    AppContext& app = window_->context();
    auto& grey = app.scene.addDataset(test::roomScan(0.2, RigidTransform(), "grey"));
    QCOMPARE(grey.style().mode, PointColorMode::Elevation);
    app.layers.setCurrentLayer(&grey);
    auto* mode = window_->findChild<QComboBox*>("colorMode");
    QVERIFY(mode);
    auto* items = qobject_cast<QStandardItemModel*>(mode->model());
    QStandardItem* rgb = items->item(int(PointColorMode::Rgb));
    QVERIFY(!rgb->isEnabled());
    QVERIFY(rgb->toolTip().contains("no RGB"));
    QVERIFY(!items->item(int(PointColorMode::Intensity))->isEnabled());
    QVERIFY(items->item(int(PointColorMode::Elevation))->isEnabled());
    QVERIFY(!app.log.toPlainText().contains("coloured by elevation"));

    app.scene.requestStyle(grey, PointStyle{PointColorMode::Rgb, "", 2.0});
    QVERIFY2(app.log.toPlainText().contains("grey.ply has no RGB colours: coloured by elevation instead"),
             qPrintable(app.log.toPlainText()));
    app.scene.requestStyle(grey, PointStyle{PointColorMode::Intensity, "", 2.0});
    QVERIFY(app.log.toPlainText().contains("grey.ply has no intensities"));

    auto& mixed = app.scene.addDataset(halfColouredRoom());
    QCOMPARE(mixed.style().mode, PointColorMode::Rgb);
    QVERIFY2(app.log.toPlainText().contains("mixed.ply: scan(s) grey have no RGB colours"),
             qPrintable(app.log.toPlainText()));
    app.layers.setCurrentLayer(&mixed);
    QVERIFY(items->item(int(PointColorMode::Rgb))->isEnabled());
  }

 private:
  std::unique_ptr<MainWindow> window_;
};

int main(int argc, char** argv) { return test::runGuiTest<GuiGuidanceTest>(argc, argv); }
#include "test_gui_guidance.moc"
