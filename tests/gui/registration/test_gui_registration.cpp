// GUI test of the registration workflow on simulated demo data (core/simulation): the indoor
// TLS scans of the "house" preset, perturbed by a known rigid transform, and the BIM model.
// Through the Registration dock's buttons: detect features, register (background task), check
// the transform against the simulation's ground truth, colour by distance, undo/redo, manual
// point pairs + ICP, project save/open, exports. Screenshots go to
// <build>/test-artifacts/gui_registration/.
#include <QApplication>
#include <QCheckBox>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QDoubleSpinBox>
#include <QFile>
#include <QRegularExpression>
#include <QSpinBox>
#include <QTest>
#include <QUndoStack>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>

#include <nlohmann/json.hpp>
#include <random>

#include "common/error.hpp"
#include "io/io.hpp"
#include "report/figure_meanings.hpp"
#include "quality/verdict_level.hpp"
#include "report/html_report.hpp"
#include "simulation/building_generator.hpp"
#include "simulation/presets.hpp"
#include "simulation/survey.hpp"
#include "gui/image_checks.hpp"
#include "gui/menu_actions.hpp"
#include "gui/open_window.hpp"
#include "gui/pdf_tools.hpp"
#include "support/test_support.hpp"
#include "ui/layers/dataset_layer.hpp"
#include "ui/layers/feature_layer.hpp"
#include "ui/layers/layer_transform.hpp"
#include "ui/layers/scan_layer.hpp"
#include "ui/layers/scene.hpp"
#include "ui/main_window.hpp"
#include "ui/panels/histogram_widget.hpp"
#include "ui/panels/log_panel.hpp"
#include "ui/project/project_file.hpp"
#include "ui/registration/manual_align_panel.hpp"
#include "ui/registration/quality_report_view.hpp"
#include "ui/registration/registration_panel.hpp"
#include "ui/registration/registration_runner.hpp"
#include "ui/registration/registration_tasks.hpp"
#include "ui/registration/report_export.hpp"
#include "ui/tasks/export_tasks.hpp"
#include "ui/tasks/task.hpp"
#include "ui/tasks/task_manager.hpp"
#include "ui/view/screenshot.hpp"
#include "ui/view/standard_view.hpp"
#include "ui/view/surface_format.hpp"
#include "ui/view/vtk_view_widget.hpp"

using namespace plumb;
using namespace plumb::ui;
using plumb::test::countColor;
using plumb::test::countHue;
using plumb::test::countNonBackground;

namespace {

constexpr int kTaskTimeoutMs = 180000;

struct Demo {
  std::filesystem::path indoor, model;
  RigidTransform truth;  ///< perturbed indoor dataset frame -> model frame
};

/// The demo survey of the house preset without the MMS pass (indoor only), written as E57,
/// and the model as PLY. Generated once per run.
const Demo& demo() {
  static const Demo d = [] {
    Demo out;
    const auto dir = test::scratchDir("gui_registration_data");
    const GeneratedBuilding b = generateBuilding(buildingPreset("house"));
    SurveyRequest r = demoSurveyRequest(b.spec, 7);
    r.mms = false;
    const SimulatedSurvey s = simulateSurvey(b.model, b.glass_triangles, b.truth.footprint, r);
    out.indoor = dir / "indoor.e57";
    out.model = dir / "model.ply";
    writeDataset(out.indoor, s.datasets.at(0).data);
    writeModel(out.model, b.model);
    out.truth = s.datasets.at(0).truth;
    return out;
  }();
  return d;
}

}  // namespace

class GuiRegistrationTest : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase() { demo(); }

  void init() {
    test::openWindowWithFiles(window_, {q(demo().indoor), q(demo().model)});
    if (QTest::currentTestFailed()) return;
    AppContext& app = window_->context();
    indoor_ = findLayerBySource(app.scene, q(demo().indoor));
    model_ = findLayerBySource(app.scene, q(demo().model));
    QVERIFY(indoor_ && model_);
    app.registration->setSourceLayer(indoor_);
    app.registration->setTargetLayer(model_);
  }
  void cleanup() { window_.reset(); }

  void detectAndRegisterThroughTheDock() {
    AppContext& app = window_->context();
    RegistrationPanel& panel = *app.registration;
    auto* detect = panel.findChild<QPushButton*>("detectFeatures");
    auto* reg = panel.findChild<QPushButton*>("register");
    QVERIFY(detect && reg && detect->isEnabled());

    QSignalSpy detected(&panel, &RegistrationPanel::featuresDetected);
    QTest::mouseClick(detect, Qt::LeftButton);
    QVERIFY(detected.wait(kTaskTimeoutMs));
    QCOMPARE(detected.at(0).at(0).toBool(), true);
    auto* scan_features = static_cast<FeatureLayer*>(featureOverlay(*indoor_));
    auto* model_features = static_cast<FeatureLayer*>(featureOverlay(*model_));
    QVERIFY(scan_features && model_features);
    QVERIFY(scan_features->features().planes.size() >= 10);
    QVERIFY(scan_features->features().segments.size() >= 10);
    QVERIFY(model_features->features().segments.size() >= 50);  // sharp edges of the model
    // The model's own planes and (PLY: untyped) window holes, drawn like the scan's (issue 14).
    QVERIFY(model_features->features().planes.size() >= 10);
    QVERIFY(!model_features->features().openings.empty());
    const QImage features = grabView(app.view);
    saveScreenshot(app.view, artefact("features.png"));
    QVERIFY(countNonBackground(features) > features.width() * features.height() / 50);

    const Eigen::Vector3d features_before = scan_features->bounds().center();
    QSignalSpy finished(&panel, &RegistrationPanel::registrationFinished);
    QTest::mouseClick(reg, Qt::LeftButton);
    QVERIFY(finished.wait(kTaskTimeoutMs));
    QVERIFY2(finished.at(0).at(0).toBool(), qPrintable(panel.report().verdict()));
    const RigidTransform T = layerTransform(*indoor_);
    const double rot = RigidTransform::rotationErrorDeg(T, demo().truth);
    const double shift = RigidTransform::translationError(T, demo().truth);
    QVERIFY2(rot < 0.2 && shift < 0.03, qPrintable(QString("rotation error %1 deg, translation error %2 m").arg(rot).arg(shift)));
    QVERIFY(panel.report().rowCount() >= 5);
    QVERIFY(panel.report().verdict().contains("succeeded"));
    // The feature overlay moved with the dataset.
    QVERIFY((scan_features->bounds().center() - T.apply(features_before)).norm() < 1e-6);

    // The registered pair on screen: shaded model (IFC type colours) and the points.
    frameIndoor();
    const QImage image = grabView(app.view);
    saveScreenshot(app.view, artefact("registered.png"));
    QVERIFY(countNonBackground(image) > image.width() * image.height() / 20);

    // Before/after toggle and undo/redo of the applied transform.
    panel.showBefore(true);
    QVERIFY(layerTransform(*indoor_).isIdentity());
    panel.showBefore(false);
    QVERIFY(RigidTransform::rotationErrorDeg(layerTransform(*indoor_), T) < 1e-9);
    QVERIFY(app.undo.canUndo());
    app.undo.undo();
    QVERIFY(layerTransform(*indoor_).isIdentity());
    app.undo.redo();
    QVERIFY(RigidTransform::translationError(layerTransform(*indoor_), T) < 1e-12);

    // Visual QA: distances to the model, legend and histogram.
    QSignalSpy distances(&panel, &RegistrationPanel::distancesComputed);
    QTest::mouseClick(panel.findChild<QPushButton*>("colourByDistance"), Qt::LeftButton);
    QVERIFY(distances.wait(kTaskTimeoutMs));
    QVERIFY(distances.at(0).at(0).toBool());
    // The distance colours are computed in the background too; the old ones stay meanwhile.
    auto* indoor = static_cast<DatasetLayer*>(indoor_);
    QCOMPARE(indoor->style().mode, PointColorMode::Distance);
    QTRY_VERIFY_WITH_TIMEOUT(!indoor->coloringPending(), kTaskTimeoutMs);
    const auto d = panel.lastDistances();
    QVERIFY(d && d->all.matched > d->all.distances.size() / 2);
    // Registered on its model: the median distance is at the noise level (2 mm sigma TLS).
    QVERIFY2(d->all.median < 0.01, qPrintable(QString::number(d->all.median)));
    // Signed distances, histogram over [-0.1, 0.1 m): most matched points within 1 cm of 0.
    const DistanceHistogram& h = panel.histogram().histogram();
    QVERIFY(d->signed_values);
    QCOMPARE(h.lo, -0.1);
    QCOMPARE(h.hi, 0.1);
    std::size_t in_bins = 0, below_cm = 0;
    for (std::size_t i = 0; i < h.counts.size(); ++i) {
      in_bins += h.counts[i];
      const double from = h.lo + double(i) * h.binWidth();
      if (from >= -0.01 - 1e-12 && from + h.binWidth() <= 0.01 + 1e-12) below_cm += h.counts[i];
    }
    QCOMPARE(in_bins, d->all.matched);
    QVERIFY2(below_cm > in_bins / 2, qPrintable(QString("%1 of %2").arg(below_cm).arg(in_bins)));
    app.scene.removeLayer(model_features);
    model_->setVisible(false);
    app.scene.layerChanged(model_);
    applyStandardView(app.view.renderer(), StandardView::Top);
    frameIndoor();
    QVERIFY(panel.legendVisible());
    const QImage qa = grabView(app.view);
    saveScreenshot(app.view, artefact("distance_colours.png"));
    // Points on the model's surfaces are near white on the blue-white-red ramp (left of the
    // legend).
    const QImage points = qa.copy(0, 0, qa.width() * 4 / 5, qa.height());
    const int white = countColor(points, QColor(247, 247, 247), 16);
    QVERIFY2(white > points.width() * points.height() / 50, qPrintable(QString::number(white)));

    // Reverting the result puts the source back.
    model_->setVisible(true);
    panel.revert();
    QVERIFY(layerTransform(*indoor_).isIdentity());
  }

  void signedDistancesUnsignedOptionAndExport() {
    AppContext& app = window_->context();
    RegistrationPanel& panel = *app.registration;
    setLayerTransform(app.scene, *indoor_, demo().truth);  // registered without running it
    colourByDistance();
    const auto d = panel.lastDistances();
    QVERIFY(d && d->signed_values && d->all.matched > d->all.distances.size() / 2);
    // Scanner noise puts points on both sides of the model's surfaces, without a bias.
    std::size_t behind = 0, in_front = 0;
    for (const float v : d->all.distances) {
      behind += v < 0 ? 1 : 0;
      in_front += v > 0 ? 1 : 0;
    }
    QVERIFY2(behind > d->all.matched / 5 && in_front > d->all.matched / 5,
             qPrintable(QString("%1 behind, %2 in front").arg(behind).arg(in_front)));
    QVERIFY2(std::abs(d->all.mean_signed) < 0.003, qPrintable(QString::number(d->all.mean_signed)));
    const auto* stats = panel.findChild<QLabel*>("distanceStats");
    QVERIFY(stats && stats->text().contains("+ in front of the target's surface"));

    // Exports carry the distances shown as the "distance" field, in each format.
    QSignalSpy idle(&app.tasks, &TaskManager::idle);
    const QStringList files = {artefact("signed.ply"), artefact("signed.e57"), artefact("signed.las")};
    for (const QString& f : files) exportRegisteredDataset(app, *indoor_, f);
    QVERIFY(idle.wait(kTaskTimeoutMs));
    QTRY_VERIFY_WITH_TIMEOUT(app.tasks.runningCount() == 0, kTaskTimeoutMs);
    QCOMPARE(app.log.errorCount(), 0);
    const Dataset& shown = static_cast<DatasetLayer*>(indoor_)->dataset();
    for (const QString& f : files) expectDistanceField(f, shown, d->per_scan);
    // The exported E57 is a new version of each scan: a GUID of its own, the one read kept as
    // its original (exports used to copy the source file's GUIDs).
    const Dataset exported = readDataset(artefact("signed.e57").toStdString());
    QCOMPARE(exported.scans.size(), shown.scans.size());
    for (std::size_t s = 0; s < shown.scans.size(); ++s) {
      QVERIFY(!shown.scans[s].guid.empty() && exported.scans[s].guid != shown.scans[s].guid);
      QCOMPARE(exported.scans[s].original_guids, std::vector<std::string>{shown.scans[s].guid});
    }

    // The unsigned option (the dock's "Signed" box): every distance >= 0, the ramp from 0.
    auto* signed_box = panel.findChild<QCheckBox*>("signed");
    QVERIFY(signed_box && signed_box->isChecked());
    signed_box->setChecked(false);
    QVERIFY(!panel.distanceParams().signed_distances);
    colourByDistance();
    const auto u = panel.lastDistances();
    QVERIFY(u && !u->signed_values);
    QVERIFY(std::none_of(u->all.distances.begin(), u->all.distances.end(), [](float v) { return v < 0; }));
    QCOMPARE(panel.histogram().histogram().lo, 0.0);
    QVERIFY(!stats->text().contains("signed"));
  }

  void manualPairsThenIcp() {
    AppContext& app = window_->context();
    ManualAlignPanel& manual = *app.manual;
    // Four well-spread points of the scans (data frame) and where the truth puts them.
    const Dataset& data = static_cast<DatasetLayer*>(indoor_)->dataset();
    const PointCloud cloud = data.merged();
    const Bounds b = cloud.bounds();
    const Eigen::Vector3d corners[] = {b.min, {b.max.x(), b.min.y(), b.min.z()},
                                       {b.min.x(), b.max.y(), b.max.z()}, b.max};
    std::mt19937 rng(3);
    for (const auto& c : corners) {
      std::size_t best = 0;
      double best_d = 1e30;
      for (std::size_t i = 0; i < cloud.size(); ++i) {
        const double dd = (cloud.world(i) - c).squaredNorm();
        if (dd < best_d) best_d = dd, best = i;
      }
      // A picking error of up to 5 cm on the target.
      std::uniform_real_distribution<double> e(-0.05, 0.05);
      const Eigen::Vector3d p = cloud.world(best);
      manual.addPair(p, demo().truth.apply(p) + Eigen::Vector3d(e(rng), e(rng), e(rng)));
    }
    QCOMPARE(manual.pairCount(), 4);
    QVERIFY(manual.align());
    for (int i = 0; i < 4; ++i) QVERIFY(manual.residual(i) >= 0 && manual.residual(i) < 0.15);
    const RigidTransform coarse = layerTransform(*indoor_);
    QVERIFY(RigidTransform::rotationErrorDeg(coarse, demo().truth) < 2.0);
    QVERIFY(RigidTransform::translationError(coarse, demo().truth) < 0.2);

    QSignalSpy finished(app.registration, &RegistrationPanel::registrationFinished);
    QVERIFY(manual.refine());
    QVERIFY(finished.wait(kTaskTimeoutMs));
    QVERIFY2(finished.at(0).at(0).toBool(), qPrintable(app.registration->report().verdict()));
    const RigidTransform fine = layerTransform(*indoor_);
    QVERIFY2(RigidTransform::rotationErrorDeg(fine, demo().truth) < 0.1 &&
                 RigidTransform::translationError(fine, demo().truth) < 0.02,
             qPrintable(QString("%1 deg %2 m")
                            .arg(RigidTransform::rotationErrorDeg(fine, demo().truth))
                            .arg(RigidTransform::translationError(fine, demo().truth))));
    // Undo goes back to the manual alignment, then to the identity.
    app.undo.undo();
    QVERIFY(RigidTransform::translationError(layerTransform(*indoor_), coarse) < 1e-12);
    app.undo.undo();
    QVERIFY(layerTransform(*indoor_).isIdentity());
  }

  // File > Export report (issue 17): the report to hand over of the registration just run,
  // the same file plumb-cli register --report writes, and its quality report as JSON.
  void exportRegistrationReportAfterRegistering() {
    AppContext& app = window_->context();
    RegistrationPanel& panel = *app.registration;
    QVERIFY(test::menuAction(*window_, "File", "Export registration report..."));
    QVERIFY_THROWS_EXCEPTION(InputError,
                             exportRegistrationReport(app, panel.lastRecord(), artefact("none.html")));
    QSignalSpy finished(&panel, &RegistrationPanel::registrationFinished);
    QVERIFY(panel.startRegistration());
    QVERIFY(finished.wait(kTaskTimeoutMs));
    QVERIFY2(finished.at(0).at(0).toBool(), qPrintable(panel.report().verdict()));
    const auto result = panel.lastResult();
    QVERIFY(result);
    QVERIFY_THROWS_EXCEPTION(InputError,
                             exportRegistrationReport(app, panel.lastRecord(), artefact("r.txt")));
    const QString html = artefact("registration-report.html"), json = artefact("quality.json");
    const QString pdf = artefact("registration-report.pdf");
    QSignalSpy idle(&app.tasks, &TaskManager::idle);
    exportRegistrationReport(app, panel.lastRecord(), html);
    exportRegistrationReport(app, panel.lastRecord(), json);
    exportRegistrationReport(app, panel.lastRecord(), pdf);
    QVERIFY(idle.wait(kTaskTimeoutMs));
    QCOMPARE(app.log.errorCount(), 0);
    std::ifstream j(json.toStdString());
    const std::string json_text((std::istreambuf_iterator<char>(j)), std::istreambuf_iterator<char>());
    QCOMPARE(json_text, qualityReportToJson(result->report));
    std::ifstream h(html.toStdString());
    const std::string page((std::istreambuf_iterator<char>(h)), std::istreambuf_iterator<char>());
    // The verdict, both inputs by name, every figure (here the RMS, as in the JSON) and the
    // four pictures (plan, section, histogram, residuals) drawn from the layers' data.
    QVERIFY(page.find(result->report.verdict.substr(0, 40)) != std::string::npos);
    QVERIFY(page.find(indoor_->name().toStdString()) != std::string::npos);
    QVERIFY(page.find(model_->name().toStdString()) != std::string::npos);
    const auto rms = nlohmann::json::parse(json_text)["points"]["rms_m"].dump();
    QVERIFY(page.find("data-json=\"points.rms_m\" data-value=\"" + rms + "\"") != std::string::npos);
    std::size_t svgs = 0;
    for (std::size_t at = page.find("<svg"); at != std::string::npos; at = page.find("<svg", at + 1)) ++svgs;
    QVERIFY2(svgs >= 4, qPrintable(QString::number(svgs)));
    checkPdfReport(pdf, json_text, result->report);
    if (QTest::currentTestFailed()) return;
    // A read-only file is not replaced: the export fails and the file keeps its content.
    const QString locked = artefact("locked.pdf");
    QFile::remove(locked);
    std::ofstream(locked.toStdString()) << "keep";
    QVERIFY(QFile::setPermissions(locked, QFileDevice::ReadOwner | QFileDevice::ReadGroup));
    exportRegistrationReport(app, panel.lastRecord(), locked);
    QVERIFY(idle.wait(kTaskTimeoutMs));
    QCOMPARE(app.log.errorCount(), 1);
    QFile kept(locked);
    QVERIFY(kept.open(QIODevice::ReadOnly));
    QCOMPARE(kept.readAll(), QByteArray("keep"));
    // A layer the registration ran on is gone: nothing to build the report from.
    app.scene.removeLayer(model_);
    QVERIFY_THROWS_EXCEPTION(InputError,
                             exportRegistrationReport(app, panel.lastRecord(), artefact("gone.html")));
  }

  /// The printable report (issue 17): a PDF of A4 pages with the verdict, every number and
  /// yes/no figure of the JSON report shown as the HTML shows it (figure name, then value, on
  /// one line), page numbers, and the pictures painted (the plan view's orange source points).
  void checkPdfReport(const QString& pdf, const std::string& json_text, const QualityReport& q) {
    QFile file(pdf);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QCOMPARE(file.read(5), QByteArray("%PDF-"));
    const QString text = test::pdfText(pdf);
    const int pages = static_cast<int>(text.count(QChar('\f')));
    QVERIFY2(pages >= 3, qPrintable(QString::number(pages)));
    QVERIFY(text.contains(QStringLiteral("Page 1 of %1").arg(pages)));
    QVERIFY(text.contains(QStringLiteral("Page %1 of %1").arg(pages)));
    const QString flat = text.simplified();
    QVERIFY(flat.contains(QStringLiteral("Verdict: %1").arg(QString::fromUtf8(verdictLevelName(q.level)))));
    QVERIFY2(flat.contains(QString::fromStdString(q.verdict).simplified()), qPrintable(flat.left(600)));
    QVERIFY(flat.contains(QStringLiteral("Sign-off")));
    int figures = 0;
    for (const auto& [path, value] : report::flattenReportJson(json_text)) {
      const auto v = nlohmann::json::parse(value);
      if (!v.is_number() && !v.is_boolean()) continue;
      const QString row = QStringLiteral("(^|\\s)%1\\s+%2(\\s|$)")
                              .arg(QRegularExpression::escape(QString::fromStdString(path)),
                                   QRegularExpression::escape(QString::fromStdString(report::displayValue(path, v))));
      QVERIFY2(QRegularExpression(row, QRegularExpression::MultilineOption).match(text).hasMatch(),
               qPrintable(QString::fromStdString(path + " = " + report::displayValue(path, v))));
      ++figures;
    }
    QVERIFY2(figures >= 10, qPrintable(QString::number(figures)));
    int orange = 0;
    for (int page = 1; page <= pages; ++page) {
      const QImage image = test::pdfPage(pdf, page, 60, artefact(QStringLiteral("report-page-%1.png").arg(page)));
      QVERIFY(!image.isNull());
      QCOMPARE(image.width(), 496);  // A4, 210 mm at 60 dpi
      orange += countHue(image, 21);
    }
    QVERIFY2(orange > 300, qPrintable(QString::number(orange)));
  }

  void projectRoundTripAndExports() {
    AppContext& app = window_->context();
    const RigidTransform T = demo().truth;
    setLayerTransform(app.scene, *indoor_, T);
    app.registration->params().refinement.final_distance = 0.03;
    // The one seed of the pipeline is in the dock's "Registration" parameters (issue 18).
    auto* seed = app.registration->findChild<QSpinBox*>("seed");
    QVERIFY(seed);
    QCOMPARE(app.registration->findChildren<QSpinBox*>("seed").size(), 1);  // no group seeds
    // Nested parameters have editors too: rotation enumeration of planes and segments.
    QCOMPARE(app.registration->findChildren<QDoubleSpinBox*>("max-tilt").size(), 2);
    QVERIFY(app.registration->findChild<QDoubleSpinBox*>("agreement-rotation"));
    seed->setValue(7);
    QCOMPARE(app.registration->params().seed, std::uint64_t{7});
    const QString project = artefact("demo.plumb.json");
    saveProject(app, project);

    // Exports of the registered cloud (E57 with poses) and of the transform (JSON).
    const QString e57 = artefact("indoor_registered.e57");
    const QString json = artefact("indoor_transform.json");
    QSignalSpy idle(&app.tasks, &TaskManager::idle);
    exportRegisteredDataset(app, *indoor_, e57);
    exportTransform(app, *indoor_, json);
    QVERIFY(idle.wait(kTaskTimeoutMs));
    QCOMPARE(app.log.errorCount(), 0);
    QVERIFY(RigidTransform::translationError(readTransformFile(json.toStdString()), T) < 1e-9);
    const Dataset exported = readDataset(e57.toStdString());
    const Dataset& original = static_cast<DatasetLayer*>(indoor_)->dataset();
    QCOMPARE(exported.pointCount(), original.pointCount());
    for (std::size_t i = 0; i < original.scans.size(); ++i)
      QVERIFY(RigidTransform::translationError(exported.scans[i].pose, T * original.scans[i].pose) < 1e-6);

    // Reopen: the scene is replaced by the project's layers with their transforms.
    app.registration->params().refinement.final_distance = 0.05;
    seed->setValue(2);
    bool done = false, ok = false;
    std::vector<Layer*> loaded;
    openProject(app, project, [&](bool all, const std::vector<Layer*>& layers) {
      done = true, ok = all, loaded = layers;
    });
    QTRY_VERIFY_WITH_TIMEOUT(done, 60000);
    QVERIFY(ok);
    QCOMPARE(app.scene.layers().size(), std::size_t{2});
    Layer* indoor = findLayerBySource(app.scene, q(demo().indoor));
    QVERIFY(indoor);
    QCOMPARE(loaded.size(), std::size_t{2});
    // Entries in saved (scene) order, each the layer read from its file.
    Layer* model = findLayerBySource(app.scene, q(demo().model));
    QVERIFY((loaded[0] == indoor && loaded[1] == model) || (loaded[0] == model && loaded[1] == indoor));
    QVERIFY(RigidTransform::translationError(layerTransform(*indoor), T) < 1e-9);
    QCOMPARE(app.registration->sourceLayer(), indoor);
    QCOMPARE(app.registration->targetLayer(), findLayerBySource(app.scene, q(demo().model)));
    QCOMPARE(app.registration->params().refinement.final_distance, 0.03);
    QCOMPARE(app.registration->params().seed, std::uint64_t{7});
    QCOMPARE(seed->value(), 7);
  }

  void projectErrorsNameTheFile() {
    const QString bad = artefact("bad.plumb.json");
    {
      std::ofstream out(bad.toStdString());
      out << "{\"plumb-project\": 1, \"layers\": [ {\"visible\": true} ]}";
    }
    try {
      openProject(window_->context(), bad);
      QFAIL("no error");
    } catch (const FileError& e) {
      QVERIFY(QString(e.what()).contains("bad.plumb.json"));
      QVERIFY(QString(e.what()).contains("layers[0]"));
    }
  }

 private:
  /// Zooms on the bulk of the indoor scans (they also see far ground through the windows).
  void colourByDistance() {
    RegistrationPanel& panel = *window_->context().registration;
    QSignalSpy done(&panel, &RegistrationPanel::distancesComputed);
    QTest::mouseClick(panel.findChild<QPushButton*>("colourByDistance"), Qt::LeftButton);
    QVERIFY(done.wait(kTaskTimeoutMs));
    QVERIFY(done.at(0).at(0).toBool());
  }

  /// `file` read back holds the field "distance" equal to `per_scan` (the points of `shown`'s
  /// scans in order; writers that drop points without coordinates drop their distance too).
  static void expectDistanceField(const QString& file, const Dataset& shown,
                                  const std::vector<std::vector<float>>& per_scan) {
    std::vector<float> all, finite;
    for (std::size_t s = 0; s < shown.scans.size(); ++s)
      for (std::size_t i = 0; i < per_scan[s].size(); ++i) {
        all.push_back(per_scan[s][i]);
        if (shown.scans[s].cloud.positions[i].allFinite()) finite.push_back(per_scan[s][i]);
      }
    std::vector<float> got;
    for (const auto& scan : readDataset(file.toStdString()).scans) {
      const ScalarField* f = scan.cloud.findScalarField("distance");
      QVERIFY2(f, qPrintable(file));
      got.insert(got.end(), f->values.begin(), f->values.end());
    }
    const std::vector<float>& expected = got.size() == all.size() ? all : finite;
    QCOMPARE(got.size(), expected.size());
    for (std::size_t i = 0; i < got.size(); ++i)
      QVERIFY2(std::isnan(got[i]) ? std::isnan(expected[i]) : got[i] == expected[i],
               qPrintable(QString("%1: point %2").arg(file).arg(i)));
  }

  void frameIndoor() {
    AppContext& app = window_->context();
    double b[6];
    app.scene.renderBounds(bulkBounds(*indoor_), b);
    zoomToBounds(app.view.renderer(), b);
  }
  static QString q(const std::filesystem::path& p) { return QString::fromStdString(p.string()); }
  QString artefact(const QString& name) {
    static const auto dir = test::scratchDir("gui_registration");
    return QString::fromStdString((dir / name.toStdString()).string());
  }
  std::unique_ptr<MainWindow> window_;
  Layer* indoor_ = nullptr;
  Layer* model_ = nullptr;
};

int main(int argc, char** argv) { return test::runGuiTest<GuiRegistrationTest>(argc, argv); }

#include "test_gui_registration.moc"
