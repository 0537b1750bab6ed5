// A saved project keeps what the user set up besides files and transforms (issue 17): each
// layer's display style and its detected features, and whether those features are up to date
// for the registration's layers and parameters. Reopened in a fresh window, "Use detected
// features" registers with them without detecting again. The distance check's settings come back
// too. On the small synthetic room
// (tests/gui/room_scene.hpp) written to PLY files.
#include <QCheckBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QGroupBox>
#include <QPushButton>
#include <QSignalSpy>
#include <QLineEdit>
#include <QSpinBox>
#include <QTest>

#include <fstream>

#include <nlohmann/json.hpp>

#include "gui/open_window.hpp"
#include "gui/room_scene.hpp"
#include "io/io.hpp"
#include "quality/cloud_distance.hpp"
#include "common/error.hpp"
#include "support/test_support.hpp"
#include "ui/layers/dataset_layer.hpp"
#include "ui/layers/feature_layer.hpp"
#include "ui/layers/layer_transform.hpp"
#include "ui/layers/model_layer.hpp"
#include "ui/layers/scene.hpp"
#include "ui/project/project_file.hpp"
#include "ui/registration/registration_panel.hpp"
#include "ui/registration/registration_tasks.hpp"

using namespace plumb;
using namespace plumb::ui;

namespace {

constexpr int kTaskTimeoutMs = 120000;

struct Files {
  QString scan, reference, model, project;
};

/// The room as two scans and a model, written once per run.
const Files& files() {
  static const Files f = [] {
    const auto dir = test::scratchDir("gui_project_state");
    writeDataset(dir / "scan.ply", *test::roomScan(0.1, test::scanOffset(), "scan"));
    writeDataset(dir / "reference.ply", *test::roomScan(0.08, RigidTransform(), "reference"));
    writeModel(dir / "model.ply", *test::roomModel());
    auto q = [&](const char* name) { return QString::fromStdString((dir / name).string()); };
    return Files{q("scan.ply"), q("reference.ply"), q("model.ply"), q("room.plumb.json")};
  }();
  return f;
}

nlohmann::json readProject() {
  std::ifstream in(files().project.toStdString());
  return nlohmann::json::parse(in);
}

/// How many layer entries of `project` name a feature file.
int featureFiles(const nlohmann::json& project) {
  int n = 0;
  for (const auto& entry : project.at("layers")) n += entry.contains("features") ? 1 : 0;
  return n;
}

std::size_t planeCount(const Layer* layer) {
  const Layer* overlay = layer ? featureOverlay(*layer) : nullptr;
  return overlay ? static_cast<const FeatureLayer*>(overlay)->features().planes.size() : 0;
}

/// The dock's "Visual check" group: the distance panel's editors (keys such as
/// "normal-neighbours" name editors of other groups too).
QWidget* visualCheck(RegistrationPanel& panel) {
  for (auto* box : panel.findChildren<QGroupBox*>())
    if (box->title() == "Visual check") return box;
  return nullptr;
}

}  // namespace

class GuiProjectStateTest : public QObject {
  Q_OBJECT

 private slots:
  void cleanup() { window_.reset(); }

  void styleAndFeaturesSurviveSaveAndOpen() {
    test::openWindowWithFiles(window_, {files().scan, files().reference, files().model});
    if (QTest::currentTestFailed()) return;
    AppContext& app = window_->context();
    auto* scan = static_cast<DatasetLayer*>(findLayerBySource(app.scene, files().scan));
    Layer* reference = findLayerBySource(app.scene, files().reference);
    auto* model = static_cast<ModelLayer*>(findLayerBySource(app.scene, files().model));
    QVERIFY(scan && reference && model);
    QCOMPARE(scan->style().mode, PointColorMode::Elevation);  // no RGB in the file
    app.scene.requestStyle(*scan, PointStyle{PointColorMode::Scan, "", 4.0});
    model->setStyle({true, 0.5});
    RegistrationPanel& panel = *app.registration;
    panel.setSourceLayer(scan);
    panel.setTargetLayer(reference);
    panel.setMethod(RegistrationMethod::Icp);
    QSignalSpy detected(&panel, &RegistrationPanel::featuresDetected);
    QVERIFY(panel.detectFeatures());
    QVERIFY(detected.wait(kTaskTimeoutMs) && detected.at(0).at(0).toBool());
    const std::size_t scan_planes = planeCount(scan), reference_planes = planeCount(reference);
    QVERIFY(scan_planes >= 4 && reference_planes >= 4);
    QVERIFY(!panel.featuresOutOfDate());
    saveProject(app, files().project);

    // The project names one feature file per layer with features, and marks them up to date.
    const nlohmann::json saved = readProject();
    QVERIFY(saved.at("registration").contains("features-detected-with"));
    QCOMPARE(featureFiles(saved), 2);
    for (std::size_t i = 0; i < saved.at("layers").size(); ++i) {
      const auto& entry = saved.at("layers")[i];
      const bool is_model = entry.at("file") == "model.ply";
      QCOMPARE(entry.contains("features"), !is_model);
      if (is_model) continue;
      const std::string name = "room.plumb.json.features/" + std::to_string(i) + ".json";
      QCOMPARE(entry.at("features").get<std::string>(), name);
      QVERIFY(QFileInfo(QFileInfo(files().project).dir(), QString::fromStdString(name)).isFile());
    }

    reopen();
    if (QTest::currentTestFailed()) return;
    AppContext& again = window_->context();
    scan = static_cast<DatasetLayer*>(findLayerBySource(again.scene, files().scan));
    reference = findLayerBySource(again.scene, files().reference);
    model = static_cast<ModelLayer*>(findLayerBySource(again.scene, files().model));
    QVERIFY(scan && reference && model);
    QCOMPARE(scan->style().mode, PointColorMode::Scan);
    QCOMPARE(scan->style().point_size, 4.0);
    QCOMPARE(static_cast<DatasetLayer*>(reference)->style().mode, PointColorMode::Elevation);
    QVERIFY(model->style().edges);
    QCOMPARE(model->style().opacity, 0.5);
    QCOMPARE(planeCount(scan), scan_planes);
    QCOMPARE(planeCount(reference), reference_planes);
    QVERIFY(!featureOverlay(*model));
    RegistrationPanel& reopened = *again.registration;
    QCOMPARE(reopened.sourceLayer(), scan);
    QCOMPARE(reopened.targetLayer(), reference);
    QVERIFY(!reopened.featuresOutOfDate());
    auto* use = reopened.findChild<QCheckBox*>("useFeatures");
    QVERIFY(use && use->isChecked() && !use->text().contains("out of date"));

    // Registering with them: no detection, no "extracting again".
    QSignalSpy finished(&reopened, &RegistrationPanel::registrationFinished);
    QTest::mouseClick(reopened.findChild<QPushButton*>("register"), Qt::LeftButton);
    QVERIFY(finished.wait(kTaskTimeoutMs));
    QVERIFY2(finished.at(0).at(0).toBool(), qPrintable(again.log.toPlainText()));
    QVERIFY(!again.log.toPlainText().contains("Detecting features"));
    QVERIFY(!again.log.toPlainText().contains("detected with other parameters"));
    QVERIFY(!layerTransform(*scan).isIdentity());
  }

  // Features saved out of date come back shown but out of date; a changed threshold after
  // reopening puts up-to-date ones out of date.
  void outOfDateFeaturesStayOutOfDate() {
    reopen();  // the project of the test above
    if (QTest::currentTestFailed()) return;
    RegistrationPanel& panel = *window_->context().registration;
    QVERIFY(!panel.featuresOutOfDate());
    panel.params().plane_extraction.max_planes /= 2;
    panel.refreshParams();
    QVERIFY(panel.featuresOutOfDate());
    saveProject(window_->context(), files().project);
    QVERIFY(!readProject().at("registration").contains("features-detected-with"));
    QCOMPARE(featureFiles(readProject()), 2);

    reopen();
    if (QTest::currentTestFailed()) return;
    RegistrationPanel& again = *window_->context().registration;
    QVERIFY(planeCount(again.sourceLayer()) > 0 && planeCount(again.targetLayer()) > 0);
    QVERIFY(again.featuresOutOfDate());
    QVERIFY(again.findChild<QCheckBox*>("useFeatures")->text().contains("out of date"));
  }

  // The distance check's settings (signed or not, search radius, neighbours for normals) come
  // back with the project; a project written without them keeps the dock's defaults.
  void distanceSettingsSurviveSaveAndOpen() {
    reopen();  // the project of the tests above
    if (QTest::currentTestFailed()) return;
    // Chosen in the dock's distance panel, as the user does.
    RegistrationPanel& panel = *window_->context().registration;
    QWidget* check = visualCheck(panel);
    QVERIFY(check);
    auto* signed_box = check->findChild<QCheckBox*>("signed");
    auto* max_distance = check->findChild<QDoubleSpinBox*>("max-distance");
    auto* neighbours = check->findChild<QSpinBox*>("normal-neighbours");
    QVERIFY(signed_box && max_distance && neighbours && signed_box->isChecked());
    signed_box->setChecked(false);
    max_distance->setValue(0.35);
    neighbours->setValue(20);
    QCOMPARE(panel.distanceParams().max_distance, 0.35);
    saveProject(window_->context(), files().project);
    const nlohmann::json saved = readProject().at("registration").at("distance-check");
    QCOMPARE(saved.at("signed").get<bool>(), false);
    QCOMPARE(saved.at("max-distance").get<double>(), 0.35);

    reopen();
    if (QTest::currentTestFailed()) return;
    const DistanceParams& restored = window_->context().registration->distanceParams();
    QCOMPARE(restored.signed_distances, false);
    QCOMPARE(restored.max_distance, 0.35);
    QCOMPARE(restored.normal_neighbours, 20);
    QWidget* shown = visualCheck(*window_->context().registration);
    QVERIFY(shown && !shown->findChild<QCheckBox*>("signed")->isChecked());
    QCOMPARE(shown->findChild<QDoubleSpinBox*>("max-distance")->value(), 0.35);
    QCOMPARE(shown->findChild<QSpinBox*>("normal-neighbours")->value(), 20);

    nlohmann::json older = readProject();
    older.at("registration").erase("distance-check");
    test::writeAll(files().project.toStdString(), older.dump(2));
    reopen();
    if (QTest::currentTestFailed()) return;
    const DistanceParams& defaults = window_->context().registration->distanceParams();
    QCOMPARE(defaults.signed_distances, DistanceParams().signed_distances);
    QCOMPARE(defaults.max_distance, DistanceParams().max_distance);
  }

  // The model target's chosen elements (issue 14) come back with the project, in the dock's
  // fields; without the entry the registration rests on the whole model; a damaged entry is an
  // error naming it.
  void modelElementsSurviveSaveAndOpen() {
    reopen();  // the project of the tests above
    if (QTest::currentTestFailed()) return;
    RegistrationPanel& panel = *window_->context().registration;
    auto* types = panel.findChild<QLineEdit*>("model-elements");
    auto* ids = panel.findChild<QLineEdit*>("model-element-ids");
    auto* storeys = panel.findChild<QLineEdit*>("model-storeys");
    QVERIFY(types && ids && storeys && types->text().isEmpty());
    QVERIFY(!readProject().at("registration").contains("model-elements"));
    types->setText("IfcWall, IfcSlab");  // typed, as the user does
    ids->setText("2O2Fr$t4X7Zf8NOew3FLOH");
    storeys->setText("Level 1,Level 2");
    saveProject(window_->context(), files().project);
    const nlohmann::json saved = readProject().at("registration").at("model-elements");
    using Names = std::vector<std::string>;
    QVERIFY(saved.at("types").get<Names>() == Names({"IfcWall", "IfcSlab"}));
    QVERIFY(saved.at("elements").get<Names>() == Names({"2O2Fr$t4X7Zf8NOew3FLOH"}));
    QVERIFY(saved.at("storeys").get<Names>() == Names({"Level 1", "Level 2"}));

    reopen();
    if (QTest::currentTestFailed()) return;
    RegistrationPanel& again = *window_->context().registration;
    QVERIFY(again.modelElements().types == Names({"IfcWall", "IfcSlab"}));
    QVERIFY(again.modelElements().elements == Names({"2O2Fr$t4X7Zf8NOew3FLOH"}));
    QCOMPARE(again.findChild<QLineEdit*>("model-elements")->text(), QString("IfcWall, IfcSlab"));
    QCOMPARE(again.findChild<QLineEdit*>("model-element-ids")->text(), QString("2O2Fr$t4X7Zf8NOew3FLOH"));
    QVERIFY(again.modelElements().storeys == Names({"Level 1", "Level 2"}));
    QCOMPARE(again.findChild<QLineEdit*>("model-storeys")->text(), QString("Level 1, Level 2"));

    nlohmann::json damaged = readProject();
    damaged.at("registration").at("model-elements")["types"] = 5;
    test::writeAll(files().project.toStdString(), damaged.dump(2));
    window_.reset();
    test::showMainWindow(window_, QSize(1400, 900));
    if (QTest::currentTestFailed()) return;
    try {
      openProject(window_->context(), files().project);
      QFAIL("a damaged model-elements entry was accepted");
    } catch (const FileError& e) {
      QVERIFY2(std::string(e.what()).find("registration.model-elements") != std::string::npos, e.what());
    }

    nlohmann::json older = readProject();
    older.at("registration").erase("model-elements");
    test::writeAll(files().project.toStdString(), older.dump(2));
    reopen();
    if (QTest::currentTestFailed()) return;
    QVERIFY(window_->context().registration->modelElements().empty());
    QVERIFY(window_->context().registration->findChild<QLineEdit*>("model-elements")->text().isEmpty());
  }

 private:
  /// A fresh window opening the project; fails the test unless every file loads.
  void reopen() {
    window_.reset();
    test::showMainWindow(window_, QSize(1400, 900));
    if (QTest::currentTestFailed()) return;
    AppContext& app = window_->context();
    bool done = false, ok = false;
    openProject(app, files().project, [&](bool all, const std::vector<Layer*>&) { done = true, ok = all; });
    QTRY_VERIFY_WITH_TIMEOUT(done, 60000);
    QVERIFY(ok);
    QVERIFY(QTest::qWaitFor([&] { return app.tasks.runningCount() == 0; }, kTaskTimeoutMs));
    QVERIFY2(app.log.errorCount() == 0, qPrintable(app.log.toPlainText()));
  }

  std::unique_ptr<MainWindow> window_;
};

int main(int argc, char** argv) { return plumb::test::runGuiTest<GuiProjectStateTest>(argc, argv); }
#include "test_gui_project_state.moc"
