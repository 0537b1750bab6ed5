// The Registration dock's work on its own (RegistrationRunner, without the dock's widgets): it
// refuses inputs it cannot work on before starting anything, one task at a time, tells when
// the features shown no longer match its inputs or parameters, and withdraws its result when
// the layer it moved goes away. On the small synthetic room (tests/gui/room_scene.hpp).
#include <QSignalSpy>
#include <QTest>
#include <QUndoStack>

#include "gui/menu_actions.hpp"
#include "gui/open_window.hpp"
#include "gui/room_scene.hpp"
#include "ui/actions/remove_layer_command.hpp"
#include "ui/layers/dataset_layer.hpp"
#include "ui/layers/layer_transform.hpp"
#include "ui/layers/model_layer.hpp"
#include "ui/layers/scene.hpp"
#include "ui/panels/log_panel.hpp"
#include "ui/registration/applied_registration.hpp"
#include "ui/registration/registration_runner.hpp"
#include "ui/registration/registration_tasks.hpp"
#include "ui/tasks/task_manager.hpp"

using namespace plumb;
using namespace plumb::ui;

namespace {
constexpr int kTaskTimeoutMs = 120000;
}

class GuiRegistrationRunnerTest : public QObject {
  Q_OBJECT

 private slots:
  void init() {
    test::showMainWindow(window_, QSize(1200, 800));
    if (QTest::currentTestFailed()) return;
    AppContext& app = window_->context();
    scan_ = &app.scene.addDataset(test::roomScan(0.1, test::scanOffset(), "scan"));
    reference_ = &app.scene.addDataset(test::roomScan(0.08, RigidTransform(), "reference"));
    runner_ = std::make_unique<RegistrationRunner>(app);
    runner_->params().method = RegistrationMethod::Icp;
  }
  void cleanup() {
    if (window_)
      QVERIFY(QTest::qWaitFor([&] { return window_->context().tasks.runningCount() == 0; }, kTaskTimeoutMs));
    runner_.reset();
    window_.reset();
  }

  // Inputs it cannot work on: nothing starts, nothing is busy, the log says why.
  void refusesInputsItCannotWorkOn() {
    AppContext& app = window_->context();
    QSignalSpy busy(runner_.get(), &RegistrationRunner::busyChanged);
    QVERIFY(!runner_->detectFeatures());
    QVERIFY2(app.log.toPlainText().contains("open a source and a target first"),
             qPrintable(app.log.toPlainText()));

    runner_->setInputs(scan_, scan_);
    QVERIFY(!runner_->detectFeatures());
    QVERIFY(!runner_->startRegistration(true));
    QVERIFY(!runner_->computeDistances());
    QCOMPARE(app.log.toPlainText().count("the source and the target are the same layer"), 3);

    Layer* model = &app.scene.addModel(test::roomModel());
    runner_->setInputs(model, reference_);
    QVERIFY(!runner_->computeDistances());
    QVERIFY(app.log.toPlainText().contains("the source must be a point dataset"));

    QCOMPARE(busy.count(), 0);
    QVERIFY(!runner_->busy());
    QCOMPARE(app.tasks.runningCount(), 0);
    QVERIFY(layerTransform(*scan_).isIdentity());
    QVERIFY(!runner_->lastResult());
  }

  // While its task runs, the next one is refused; then it is ready again.
  void runsOneTaskAtATime() {
    AppContext& app = window_->context();
    runner_->setInputs(scan_, reference_);
    QSignalSpy detected(runner_.get(), &RegistrationRunner::featuresDetected);
    QVERIFY(runner_->detectFeatures());
    QVERIFY(runner_->busy());
    QVERIFY(!runner_->startRegistration(false));
    QVERIFY(app.log.toPlainText().contains("a task is already running"));
    QVERIFY(detected.wait(kTaskTimeoutMs));
    QVERIFY2(detected.at(0).at(0).toBool(), qPrintable(app.log.toPlainText()));
    QVERIFY(!runner_->busy());
    QSignalSpy finished(runner_.get(), &RegistrationRunner::registrationFinished);
    QVERIFY(runner_->startRegistration(false));
    QVERIFY(finished.wait(kTaskTimeoutMs));
    QVERIFY2(finished.at(0).at(0).toBool(), qPrintable(app.log.toPlainText()));
  }

  // The features shown are up to date only for the layers and extraction parameters they were
  // detected with; registering with out-of-date ones extracts them again and says so.
  void featuresGoOutOfDateWithTheirInputs() {
    AppContext& app = window_->context();
    runner_->setInputs(scan_, reference_);
    QVERIFY(!runner_->featuresShown() && !runner_->featuresUpToDate());
    QSignalSpy detected(runner_.get(), &RegistrationRunner::featuresDetected);
    QVERIFY(runner_->detectFeatures());
    QVERIFY(detected.wait(kTaskTimeoutMs) && detected.at(0).at(0).toBool());
    QVERIFY(runner_->featuresShown() && runner_->featuresUpToDate());

    int& planes = runner_->params().plane_extraction.max_planes;
    const int detected_with = planes;
    planes = detected_with / 2;
    QVERIFY(runner_->featuresShown() && !runner_->featuresUpToDate());
    runner_->params().refinement.final_distance *= 2;  // not an extraction parameter
    planes = detected_with;
    QVERIFY(runner_->featuresUpToDate());

    runner_->setInputs(reference_, scan_);  // both still show features, detected the other way
    QVERIFY(runner_->featuresShown() && !runner_->featuresUpToDate());
    QVERIFY(!app.log.toPlainText().contains("detected with other parameters"));
    QSignalSpy finished(runner_.get(), &RegistrationRunner::registrationFinished);
    QVERIFY(runner_->startRegistration(true));
    QVERIFY(finished.wait(kTaskTimeoutMs));
    QVERIFY(app.log.toPlainText().contains("detected with other parameters"));
  }

  // The result is applied to the layer the task started with (undoable); a new one replaces
  // it; when that layer goes away, the result goes with it.
  void withdrawsTheResultOfARemovedLayer() {
    AppContext& app = window_->context();
    runner_->setInputs(scan_, reference_);
    QSignalSpy results(runner_.get(), &RegistrationRunner::newResult);
    QSignalSpy finished(runner_.get(), &RegistrationRunner::registrationFinished);
    QVERIFY(runner_->startRegistration(false));
    runner_->setInputs(reference_, scan_);  // chosen while it runs: changes nothing for it
    QVERIFY(finished.wait(kTaskTimeoutMs));
    QVERIFY2(finished.at(0).at(0).toBool(), qPrintable(app.log.toPlainText()));
    QCOMPARE(results.count(), 1);
    const auto first = runner_->lastResult();
    QVERIFY(first && first->success());
    QCOMPARE(runner_->applied().layer(), scan_);
    QVERIFY(runner_->applied().inEffect());
    QVERIFY(RigidTransform::translationError(layerTransform(*scan_), test::scanOffset().inverse()) < 0.01);
    QVERIFY(layerTransform(*reference_).isIdentity());
    QCOMPARE(app.undo.count(), 1);

    runner_->setInputs(scan_, reference_);
    QVERIFY(runner_->startRegistration(false));
    QVERIFY(finished.wait(kTaskTimeoutMs));
    QCOMPARE(results.count(), 2);
    QVERIFY(runner_->lastResult() && runner_->lastResult() != first);

    QSignalSpy withdrawn(runner_.get(), &RegistrationRunner::resultWithdrawn);
    app.scene.removeLayer(reference_);  // not the layer it moved: the result stays
    QCOMPARE(withdrawn.count(), 0);
    QVERIFY(runner_->lastResult());
    app.scene.removeLayer(scan_);
    scan_ = reference_ = nullptr;
    QCOMPARE(withdrawn.count(), 1);
    QVERIFY(!runner_->lastResult());
    QVERIFY(runner_->applied().layer() == nullptr && !runner_->applied().inEffect());
  }

  // Edit > Undo and Redo wait while its task holds the layers: Redo of "Remove scan" would take
  // the scan away under the registration. Afterwards they step through the history again,
  // the registration included.
  void undoAndRedoWaitForItsTask() {
    AppContext& app = window_->context();
    QAction* undo = test::menuAction(*window_, "Edit", "Undo");
    QAction* redo = test::menuAction(*window_, "Edit", "Redo");
    QVERIFY(undo && redo);
    app.undo.push(new RemoveLayerCommand(app.scene, *scan_));
    app.undo.undo();
    QVERIFY(!undo->isEnabled() && redo->isEnabled());
    runner_->setInputs(scan_, reference_);
    QSignalSpy finished(runner_.get(), &RegistrationRunner::registrationFinished);
    QVERIFY(runner_->startRegistration(false));
    QVERIFY(!redo->isEnabled());
    redo->trigger();
    QCOMPARE(app.scene.layers().size(), std::size_t{2});
    QCOMPARE(app.undo.index(), 0);

    QVERIFY(finished.wait(kTaskTimeoutMs));
    QVERIFY2(finished.at(0).at(0).toBool(), qPrintable(app.log.toPlainText()));
    QCOMPARE(runner_->applied().layer(), scan_);
    QVERIFY(undo->isEnabled() && !redo->isEnabled());  // the registration replaced the removal
    undo->trigger();
    QVERIFY(layerTransform(*scan_).isIdentity());
    QVERIFY(redo->isEnabled());
    redo->trigger();
    QVERIFY(RigidTransform::translationError(layerTransform(*scan_), test::scanOffset().inverse()) < 0.01);
  }

  // Registration on chosen elements (issue 14): a type the model lacks stops the task with
  // the types it has; the model's own type registers, and the record keeps the choice for
  // the report.
  void registersOntoChosenModelElements() {
    AppContext& app = window_->context();
    Layer* model = &app.scene.addModel(test::roomModel());
    runner_->setInputs(scan_, model);
    runner_->modelElements().types = {"IfcSlab"};
    QSignalSpy finished(runner_.get(), &RegistrationRunner::registrationFinished);
    QVERIFY(runner_->startRegistration(false));
    QVERIFY(finished.wait(kTaskTimeoutMs));
    QVERIFY(!finished.at(0).at(0).toBool());
    QVERIFY2(app.log.toPlainText().contains("no element of type 'IfcSlab' (the model has IfcWall)"),
             qPrintable(app.log.toPlainText()));
    QVERIFY(layerTransform(*scan_).isIdentity());

    runner_->modelElements().types = {"IfcWall"};
    QVERIFY(runner_->startRegistration(false));
    QVERIFY(finished.wait(kTaskTimeoutMs));
    QVERIFY2(finished.at(1).at(0).toBool(), qPrintable(app.log.toPlainText()));
    QCOMPARE(runner_->lastRecord().target_elements.types, std::vector<std::string>{"IfcWall"});
    QVERIFY(RigidTransform::translationError(layerTransform(*scan_), test::scanOffset().inverse()) < 0.01);
  }

 private:
  std::unique_ptr<MainWindow> window_;
  std::unique_ptr<RegistrationRunner> runner_;
  Layer* scan_ = nullptr;
  Layer* reference_ = nullptr;
};

int main(int argc, char** argv) { return test::runGuiTest<GuiRegistrationRunnerTest>(argc, argv); }

#include "test_gui_registration_runner.moc"
