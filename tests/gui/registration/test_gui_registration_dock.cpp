// The Registration dock keeps its promises while it works and after (issue 17): a running task
// holds its layers (Remove layer, Open project, Undo and Redo wait, the layer choice is
// locked), and a result whose layer went away anyway is dropped instead of landing on another
// layer. Attaching a trajectory holds its layer likewise; exports and loads work on copies and
// hold none. On a small synthetic room (tests/gui/room_scene.hpp) so each task takes a second
// or two.
#include <QApplication>
#include <QCheckBox>
#include <QLineEdit>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QSlider>
#include <QUndoStack>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QSignalSpy>
#include <QTest>

#include <fstream>
#include <variant>

#include "gui/menu_actions.hpp"
#include "gui/open_window.hpp"
#include "gui/room_scene.hpp"
#include "support/test_support.hpp"
#include "io/io.hpp"
#include "ui/actions/file_dialogs.hpp"
#include "ui/layers/dataset_layer.hpp"
#include "ui/layers/layer_transform.hpp"
#include "ui/layers/model_layer.hpp"
#include "ui/layers/scene.hpp"
#include "ui/panels/layer_tree_panel.hpp"
#include "ui/panels/log_panel.hpp"
#include "ui/panels/histogram_widget.hpp"
#include "ui/registration/quality_report_view.hpp"
#include "ui/registration/registration_panel.hpp"
#include "ui/registration/registration_tasks.hpp"
#include "ui/registration/transform_command.hpp"
#include "ui/tasks/attach_trajectory.hpp"
#include "ui/tasks/export_tasks.hpp"
#include "ui/tasks/load_files.hpp"
#include "ui/tasks/task_manager.hpp"
#include "ui/view/surface_format.hpp"

using namespace plumb;
using namespace plumb::ui;

namespace {

constexpr int kTaskTimeoutMs = 120000;

/// An empty project: opening it would clear the scene.
QString emptyProject() {
  static const QString path = [] {
    const auto file = test::scratchDir("gui_registration_dock") / "empty.plumb.json";
    std::ofstream(file) << R"({"plumb-project": 1, "layers": []})";
    return QString::fromStdString(file.string());
  }();
  return path;
}

QString q(const std::filesystem::path& p) { return QString::fromStdString(p.string()); }

}  // namespace

class GuiRegistrationDockTest : public QObject {
  Q_OBJECT

 private slots:
  void init() {
    test::showMainWindow(window_, QSize(1400, 900));
    if (QTest::currentTestFailed()) return;
    AppContext& app = window_->context();
    // With timestamps (no effect on registration without scan poses): a trajectory can be attached.
    scan_ = &app.scene.addDataset(test::withTimestamps(test::roomScan(0.1, test::scanOffset(), "scan")));
    reference_ = &app.scene.addDataset(test::roomScan(0.08, RigidTransform(), "reference"));
    RegistrationPanel& panel = *app.registration;
    panel.setSourceLayer(scan_);
    panel.setTargetLayer(reference_);
    panel.setMethod(RegistrationMethod::Icp);
    for (auto signal : {&RegistrationPanel::featuresDetected, &RegistrationPanel::registrationFinished,
                        &RegistrationPanel::distancesComputed})
      connect(&panel, signal, this, [this](bool ok) {
        lastOk_ = ok;
        ++finished_;
      });
    setFileChooser([](FileRequest, const QString&, const QString&, const QString&) {
      return QStringList{emptyProject()};
    });
  }
  void cleanup() {
    setFileChooser({});
    window_.reset();
  }

  void tasks_data() {
    QTest::addColumn<QString>("button");
    QTest::newRow("detect features") << "detectFeatures";
    QTest::newRow("register") << "register";
    QTest::newRow("colour by distance") << "colourByDistance";
    QTest::newRow("attach trajectory") << "attachTrajectory";
  }

  // While a task runs, nothing the user can do removes or swaps the layers it works on; when
  // it is done, the actions come back and the result is on the layers it started with.
  void aRunningTaskHoldsItsLayers_data() { tasks_data(); }
  void aRunningTaskHoldsItsLayers() {
    QFETCH(QString, button);
    AppContext& app = window_->context();
    RegistrationPanel& panel = *app.registration;
    QAction* remove = test::menuAction(*window_, "Edit", "Remove layer");
    QAction* open = test::menuAction(*window_, "File", "Open project...");
    QAction* undo = test::menuAction(*window_, "Edit", "Undo");
    QAction* redo = test::menuAction(*window_, "Edit", "Redo");
    QVERIFY(remove && open && undo && redo);
    app.layers.setCurrentLayer(scan_);
    QVERIFY(remove->isEnabled() && open->isEnabled());
    // A history to step through: Undo would undo a transform, Redo would remove the scan again.
    app.undo.push(new TransformCommand(app.scene, *reference_, RigidTransform(), RigidTransform(), "keep"));
    remove->trigger();
    undo->trigger();
    QCOMPARE(app.scene.layers().size(), std::size_t{2});
    QVERIFY(undo->isEnabled() && redo->isEnabled());
    panel.setSourceLayer(scan_);
    panel.setTargetLayer(reference_);
    const int history = app.undo.index();

    const int done = startTask(button);
    const bool dock = button != "attachTrajectory";  // attaching holds the scan only
    auto* source = panel.findChild<QComboBox*>("sourceLayer");
    auto* target = panel.findChild<QComboBox*>("targetLayer");
    QCOMPARE(!source->isEnabled() && !target->isEnabled(), dock);
    for (Layer* layer : {scan_, reference_}) {
      app.layers.setCurrentLayer(layer);
      const bool held = dock || layer == scan_;
      QVERIFY2(remove->isEnabled() == !held, qPrintable(layer->name()));
      if (held) remove->trigger();
    }
    QVERIFY(!open->isEnabled() && !undo->isEnabled() && !redo->isEnabled());
    open->trigger();
    redo->trigger();
    undo->trigger();
    QCOMPARE(app.scene.layers().size(), std::size_t{2});
    QCOMPARE(app.undo.index(), history);

    QVERIFY(waitForTask(done));
    QVERIFY2(lastOk_, qPrintable(app.log.toPlainText()));
    QVERIFY(source->isEnabled() && target->isEnabled());
    QVERIFY(remove->isEnabled() && open->isEnabled() && undo->isEnabled());
    QCOMPARE(redo->isEnabled(), app.undo.canRedo());
    QCOMPARE(panel.sourceLayer(), scan_);
    if (button == "attachTrajectory")
      QVERIFY(static_cast<DatasetLayer*>(scan_)->dataset().scans[0].cloud.hasSensorOrigins());
    if (button == "register") {
      // ICP put the scan back where the reference is; the reference did not move.
      QVERIFY(RigidTransform::translationError(layerTransform(*scan_), test::scanOffset().inverse()) < 0.01);
      QVERIFY(layerTransform(*reference_).isIdentity());
    }
  }

  // A layer removed by other means while a task runs (the scene API, a script): the task
  // finishes with an error naming it, and its result goes nowhere (before, the registration
  // moved whatever was selected as the source by then, the others touched freed layers).
  void aResultWhoseLayerWentAwayIsDropped_data() { tasks_data(); }
  void aResultWhoseLayerWentAwayIsDropped() {
    QFETCH(QString, button);
    AppContext& app = window_->context();
    const int done = startTask(button);
    app.scene.removeLayer(scan_);
    scan_ = nullptr;
    QVERIFY(waitForTask(done));
    QVERIFY(!lastOk_);
    QVERIFY2(app.log.toPlainText().contains("'scan.ply' was removed"), qPrintable(app.log.toPlainText()));
    QVERIFY(layerTransform(*reference_).isIdentity());
    QVERIFY(featureOverlay(*reference_) == nullptr);
    QVERIFY(!static_cast<DatasetLayer*>(reference_)->hasDistances());
  }

  // Exports and loads work on copies and hold no layer: the scan may be removed (and the
  // removal undone) while they run, and their result is whole.
  void aTaskOnACopyHoldsNoLayer_data() {
    QTest::addColumn<QString>("button");
    QTest::newRow("export") << "export";
    QTest::newRow("load") << "load";
  }
  void aTaskOnACopyHoldsNoLayer() {
    QFETCH(QString, button);
    AppContext& app = window_->context();
    QAction* remove = test::menuAction(*window_, "Edit", "Remove layer");
    QAction* undo = test::menuAction(*window_, "Edit", "Undo");
    QVERIFY(remove && undo);
    const std::size_t points = static_cast<DatasetLayer*>(scan_)->dataset().pointCount();
    const int done = startTask(button);
    QVERIFY(!app.tasks.holdsLayers());
    app.layers.setCurrentLayer(scan_);
    QVERIFY(remove->isEnabled());
    remove->trigger();
    QCOMPARE(app.scene.layers().size(), std::size_t{1});
    QVERIFY(undo->isEnabled());
    QVERIFY(waitForTask(done));
    QVERIFY2(lastOk_ && app.log.errorCount() == 0, qPrintable(app.log.toPlainText()));
    if (button == "export") {
      const LoadedData written = readFile(work_ / "exported.ply");
      QCOMPARE(std::get<Dataset>(written).pointCount(), points);
    } else {
      QCOMPARE(app.scene.layers().size(), std::size_t{2});
      QCOMPARE(app.scene.layers().back()->name(), QString("loaded.ply"));
    }
    undo->trigger();
    QCOMPARE(app.scene.layers().front().get(), scan_);
  }

  // Whatever order the files come in, the dock proposes the scan as the source and the model
  // (else the largest dataset) as the target, so the first click on Register registers (it
  // proposed the first layer twice: "the source and the target are the same layer").
  void theFirstClickOnRegisterWorks_data() {
    QTest::addColumn<bool>("model");
    QTest::addColumn<bool>("targetFirst");
    QTest::newRow("scan, then model") << true << false;
    QTest::newRow("model, then scan") << true << true;
    QTest::newRow("scan, then larger scan") << false << false;
    QTest::newRow("larger scan, then scan") << false << true;
  }
  void theFirstClickOnRegisterWorks() {
    QFETCH(bool, model);
    QFETCH(bool, targetFirst);
    AppContext& app = window_->context();
    RegistrationPanel& panel = *app.registration;
    app.scene.clear();
    const auto addTarget = [&]() -> Layer* {
      if (model) return &app.scene.addModel(test::roomModel());
      return &app.scene.addDataset(test::roomScan(0.08, RigidTransform(), "reference"));
    };
    Layer* target = targetFirst ? addTarget() : nullptr;
    Layer* scan = &app.scene.addDataset(test::roomScan(0.1, test::scanOffset(), "scan"));
    if (!targetFirst) target = addTarget();
    QCOMPARE(panel.sourceLayer(), scan);
    QCOMPARE(panel.targetLayer(), target);

    panel.setMethod(RegistrationMethod::Icp);
    const int done = startTask("register");
    QVERIFY2(waitForTask(done), qPrintable(app.log.toPlainText()));
    QVERIFY2(lastOk_, qPrintable(app.log.toPlainText()));
    QVERIFY(RigidTransform::translationError(layerTransform(*scan), test::scanOffset().inverse()) < 0.01);
  }

  // The report, Accept/Revert and the distance check describe the result only while it is in
  // effect: Undo withdraws them (Redo brings the report back), a new registration drops the
  // old distance check, Open project drops the report (all stayed as they were before).
  void staleResultsAreWithdrawn() {
    AppContext& app = window_->context();
    RegistrationPanel& panel = *app.registration;
    auto* accept = panel.findChild<QPushButton*>("acceptResult");
    auto* revert = panel.findChild<QPushButton*>("revertResult");
    auto* scan = static_cast<DatasetLayer*>(scan_);
    QVERIFY(waitForTask(startTask("register")) && lastOk_);
    QVERIFY(!panel.report().level().isEmpty());
    QVERIFY(accept->isEnabled() && revert->isEnabled());
    QVERIFY(waitForTask(startTask("colourByDistance")) && lastOk_);
    QVERIFY(panel.legendVisible() && scan->hasDistances());
    QVERIFY(!panel.histogram().histogram().counts.empty());

    app.undo.undo();
    QVERIFY(layerTransform(*scan_).isIdentity());
    QVERIFY(panel.report().level().isEmpty());
    QCOMPARE(panel.report().rowCount(), 0);
    QVERIFY2(panel.report().verdict().contains("undone"), qPrintable(panel.report().verdict()));
    QVERIFY(!accept->isEnabled() && !revert->isEnabled());
    QVERIFY(!panel.legendVisible() && !scan->hasDistances());
    QVERIFY(scan->style().mode != PointColorMode::Distance);
    QVERIFY(panel.histogram().histogram().counts.empty());
    app.undo.redo();
    QVERIFY(!panel.report().level().isEmpty());
    QVERIFY(accept->isEnabled() && revert->isEnabled());

    // Registering onto another target: the distances to the first one go.
    QVERIFY(waitForTask(startTask("colourByDistance")) && lastOk_);
    Layer* other = &app.scene.addDataset(test::roomScan(0.09, RigidTransform(), "other"));
    panel.setTargetLayer(other);
    QVERIFY(waitForTask(startTask("register")) && lastOk_);
    QVERIFY(!panel.legendVisible() && !scan->hasDistances());
    QVERIFY(panel.histogram().histogram().counts.empty());
    QVERIFY(!panel.report().level().isEmpty());

    // Open project: the report of the layers it replaced goes.
    test::menuAction(*window_, "File", "Open project...")->trigger();
    QTRY_VERIFY(app.scene.layers().empty());
    QVERIFY(panel.report().level().isEmpty());
    QCOMPARE(panel.report().rowCount(), 0);
    QVERIFY(!accept->isEnabled() && !revert->isEnabled());
  }

  // Features detected with other extraction parameters are marked out of date and not used:
  // Register extracts again and says so (before, they were reused silently).
  void featuresDetectedWithOtherParametersAreNotReused() {
    AppContext& app = window_->context();
    RegistrationPanel& panel = *app.registration;
    auto* use = panel.findChild<QCheckBox*>("useFeatures");
    QVERIFY(waitForTask(startTask("detectFeatures")) && lastOk_);
    QVERIFY(use->isChecked() && !use->text().contains("out of date"));
    auto* planes = panel.findChild<QSpinBox*>("max-planes");
    planes->setValue(planes->value() / 2);  // as typed in
    QVERIFY2(use->text().contains("out of date"), qPrintable(use->text()));
    QVERIFY(waitForTask(startTask("register")) && lastOk_);
    QVERIFY(app.log.toPlainText().contains("detected with other parameters"));
    // Detected again with these parameters: up to date.
    QVERIFY(waitForTask(startTask("detectFeatures")) && lastOk_);
    QVERIFY(!use->text().contains("out of date"));
  }

  // The model element fields (issue 14) come from the option list, and typing a choice makes
  // the features shown out of date, like a parameter.
  void modelElementFieldsMarkFeaturesOutOfDate() {
    AppContext& app = window_->context();
    RegistrationPanel& panel = *app.registration;
    auto* types = panel.findChild<QLineEdit*>("model-elements");
    QVERIFY(types && panel.findChild<QLineEdit*>("model-element-ids"));
    auto* use = panel.findChild<QCheckBox*>("useFeatures");
    QVERIFY(waitForTask(startTask("detectFeatures")) && lastOk_);
    QVERIFY(!use->text().contains("out of date"));
    QTest::keyClicks(types, "IfcWall, IfcSlab");
    QVERIFY2(use->text().contains("out of date"), qPrintable(use->text()));
    types->clear();
    QVERIFY(!use->text().contains("out of date"));
  }

  // Edit > Remove layer is undoable and keeps the history of the other layers (it cleared the
  // whole undo stack, without asking).
  void removingALayerKeepsTheHistory() {
    AppContext& app = window_->context();
    QAction* remove = test::menuAction(*window_, "Edit", "Remove layer");
    QVERIFY(waitForTask(startTask("register")) && lastOk_);
    const RigidTransform registered = layerTransform(*scan_);
    const RigidTransform moved(Eigen::Matrix3d::Identity(), Eigen::Vector3d(1, 2, 3));
    app.undo.push(new TransformCommand(app.scene, *reference_, RigidTransform(), moved, "move"));
    Layer* extra = &app.scene.addDataset(test::roomScan(0.2, RigidTransform(), "extra"));
    QCOMPARE(app.undo.count(), 2);

    app.layers.setCurrentLayer(extra);
    remove->trigger();
    QCOMPARE(app.scene.layers().size(), std::size_t{2});
    QCOMPARE(app.undo.count(), 3);
    app.undo.undo();  // the layer is back, in its place
    QCOMPARE(app.scene.layers().size(), std::size_t{3});
    QCOMPARE(app.scene.layers().back().get(), extra);
    app.undo.undo();
    QVERIFY(layerTransform(*reference_).isIdentity());
    app.undo.undo();
    QVERIFY(layerTransform(*scan_).isIdentity());
    app.undo.redo();
    app.undo.redo();
    QVERIFY(RigidTransform::translationError(layerTransform(*scan_), registered) < 1e-12);
    QVERIFY(RigidTransform::translationError(layerTransform(*reference_), moved) < 1e-12);

    // Removing the registered scan itself: undoing it brings it back with its history.
    app.layers.setCurrentLayer(scan_);
    remove->trigger();
    QCOMPARE(app.scene.layers().size(), std::size_t{2});
    app.undo.undo();
    QCOMPARE(app.scene.layers().front().get(), scan_);
    app.undo.undo();
    app.undo.undo();
    QVERIFY(layerTransform(*scan_).isIdentity());
  }

  // The wheel over the dock scrolls past the parameters; it changes a value only once the
  // user clicked into it, the changed value's label turns bold, and the group's "Reset to
  // defaults" puts it back (before, scrolling the dock turned "Maximum planes" from 60 to 63).
  void theWheelChangesOnlyFocusedParameters() {
    AppContext& app = window_->context();
    RegistrationPanel& panel = *app.registration;
    auto* planes = panel.findChild<QSpinBox*>("max-planes");
    auto* method = panel.findChild<QComboBox*>("method");
    QVERIFY(planes && method);
    const int defaults = panel.params().plane_extraction.max_planes;
    const int method_index = method->currentIndex();
    QVERIFY(!planes->hasFocus() && !method->hasFocus());
    wheel(planes, -3);
    wheel(method, -1);
    QCOMPARE(planes->value(), defaults);
    QCOMPARE(panel.params().plane_extraction.max_planes, defaults);
    QCOMPARE(method->currentIndex(), method_index);
    QLabel* label = labelFor(panel, "Maximum planes");
    QVERIFY(label && !label->font().bold());

    window_->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(window_.get()));
    planes->setFocus(Qt::MouseFocusReason);
    QTRY_VERIFY(planes->hasFocus());
    wheel(planes, 1);
    QVERIFY(planes->value() != defaults);
    QCOMPARE(panel.params().plane_extraction.max_planes, planes->value());
    QVERIFY(label->font().bold());
    QVERIFY(label->toolTip().contains(QString::number(defaults)));

    auto* reset = planes->parentWidget()->findChild<QPushButton*>("resetToDefaults");
    QVERIFY(reset && reset->isEnabled());
    QTest::mouseClick(reset, Qt::LeftButton);
    QCOMPARE(planes->value(), defaults);
    QCOMPARE(panel.params().plane_extraction.max_planes, defaults);
    QVERIFY(!label->font().bold());
    QVERIFY(!reset->isEnabled());
  }

  // The same in the Properties dock's style editors: colour mode, point size and a model's
  // opacity change by wheel only once clicked into.
  void theWheelChangesOnlyFocusedStyleEditors() {
    AppContext& app = window_->context();
    app.layers.setCurrentLayer(scan_);
    auto* mode = window_->findChild<QComboBox*>("colorMode");
    auto* size = window_->findChild<QDoubleSpinBox*>("pointSize");
    QVERIFY(mode && size && size->isVisible());
    const int mode_index = mode->currentIndex();
    const double point_size = size->value();
    QVERIFY(!mode->hasFocus() && !size->hasFocus());
    wheel(mode, -1);
    wheel(size, 2);
    QCOMPARE(mode->currentIndex(), mode_index);
    QCOMPARE(size->value(), point_size);
    QCOMPARE(static_cast<DatasetLayer*>(scan_)->style().point_size, point_size);

    window_->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(window_.get()));
    size->setFocus(Qt::MouseFocusReason);
    QTRY_VERIFY(size->hasFocus());
    wheel(size, 2);
    QVERIFY(size->value() > point_size);
    QCOMPARE(static_cast<DatasetLayer*>(scan_)->style().point_size, size->value());

    auto* model = &app.scene.addModel(test::roomModel());
    app.layers.setCurrentLayer(model);
    auto* opacity = window_->findChild<QSlider*>("meshOpacity");
    QVERIFY(opacity && opacity->isVisible() && !opacity->hasFocus());
    const int percent = opacity->value();
    wheel(opacity, -2);
    QCOMPARE(opacity->value(), percent);
    QCOMPARE(model->style().opacity, percent / 100.0);
    opacity->setFocus(Qt::MouseFocusReason);
    QTRY_VERIFY(opacity->hasFocus());
    wheel(opacity, -2);
    QVERIFY(opacity->value() < percent);
    QCOMPARE(model->style().opacity, opacity->value() / 100.0);
  }

 private:
  /// One wheel notch (`notches` of them, up when positive) over the middle of `w`, delivered
  /// the way Qt delivers it (to the widget, then its parents while ignored).
  static void wheel(QWidget* w, int notches) {
    const QPointF at(w->width() / 2.0, w->height() / 2.0);
    QWheelEvent e(at, w->mapToGlobal(at), QPoint(), QPoint(0, 120 * notches), Qt::NoButton,
                  Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(w, &e);
  }
  static QLabel* labelFor(const QWidget& panel, const QString& text) {
    for (QLabel* l : panel.findChildren<QLabel*>())
      if (l->text() == text) return l;
    return nullptr;
  }
  /// Clicks the dock's `button`, or starts "attachTrajectory" (to the scan), "export" (the scan)
  /// or "load" (a copy of the scan as loaded.ply); returns how many results were reported before.
  int startTask(const QString& button) {
    AppContext& app = window_->context();
    const int before = finished_;
    const auto report = [this](bool ok) {
      lastOk_ = ok;
      ++finished_;
    };
    work_ = test::scratchDir("gui_registration_dock_tasks");
    if (button == "attachTrajectory") {
      auto& scan = static_cast<DatasetLayer&>(*scan_);
      startAttachTrajectory(app, scan, q(test::writeRoomTrajectory(work_ / "trajectory.txt", scan.dataset().pointCount())),
                            report);
    } else if (button == "export") {
      connect(exportRegisteredDataset(app, *scan_, q(work_ / "exported.ply")), &Task::finished, this, report);
    } else if (button == "load") {
      writeDataset(work_ / "loaded.ply", static_cast<DatasetLayer&>(*scan_).dataset());
      loadFiles(app, {q(work_ / "loaded.ply")}, {}, [report](const QString&, bool ok) { report(ok); });
    } else {
      auto* b = app.registration->findChild<QPushButton*>(button);
      if (!b || !b->isEnabled()) return -1;
      QTest::mouseClick(b, Qt::LeftButton);
    }
    return before;
  }
  bool waitForTask(int before) {
    if (before < 0) return false;
    // Recolouring the distances runs after: let every task end before the window goes.
    return QTest::qWaitFor([&] { return finished_ > before; }, kTaskTimeoutMs) &&
           QTest::qWaitFor([&] { return window_->context().tasks.runningCount() == 0; },
                           kTaskTimeoutMs);
  }

  std::unique_ptr<MainWindow> window_;
  std::filesystem::path work_;  ///< files of the task started last
  Layer* scan_ = nullptr;
  Layer* reference_ = nullptr;
  int finished_ = 0;
  bool lastOk_ = false;
};

int main(int argc, char** argv) { return test::runGuiTest<GuiRegistrationDockTest>(argc, argv); }

#include "test_gui_registration_dock.moc"
