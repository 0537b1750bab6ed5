// GUI tests that drive the desktop application as a user does: File > Open (the file dialog
// answered through the setFileChooser hook), drag and drop onto the main window, File > Recent
// files, Save/Open project and Export screenshot through the menu, mouse clicks in the 3D view
// at the projected position of known features (properties shown) and of known points (manual
// point pairs), a mouse drag that switches the view to level of detail and back, and the still
// frame after a drag kept to its time budget (a subset of a 5 M point cloud under software GL,
// reported in the status bar) unless View > Full detail when still is on.
// Screenshots are saved under <build>/test-artifacts/gui_interaction/.
#include <QApplication>
#include <QComboBox>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QSignalSpy>
#include <QStandardItemModel>
#include <QTest>
#include <QUrl>

#include <vtkRenderer.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

#include "gui/feature_fixtures.hpp"
#include "gui/grid_ply.hpp"
#include "gui/image_checks.hpp"
#include "gui/menu_actions.hpp"
#include "gui/open_window.hpp"
#include "gui/view_clicks.hpp"
#include "support/test_support.hpp"
#include "ui/actions/file_dialogs.hpp"
#include "ui/actions/recent_files.hpp"
#include "ui/layers/color_ramp.hpp"
#include "ui/layers/dataset_layer.hpp"
#include "ui/layers/layer_transform.hpp"
#include "ui/layers/model_layer.hpp"
#include "ui/layers/scene.hpp"
#include "ui/main_window.hpp"
#include "ui/panels/layer_tree_panel.hpp"
#include "ui/panels/log_panel.hpp"
#include "ui/panels/properties_panel.hpp"
#include "ui/registration/manual_align_panel.hpp"
#include "ui/registration/registration_panel.hpp"
#include "ui/tasks/task_manager.hpp"
#include "ui/view/lod_budget.hpp"
#include "ui/view/lod_controller.hpp"
#include "ui/view/screenshot.hpp"
#include "ui/view/standard_view.hpp"
#include "ui/view/surface_format.hpp"
#include "ui/view/vtk_view_widget.hpp"

using namespace plumb;
using namespace plumb::ui;
using plumb::test::menuAction;
using plumb::test::plainLabel;
using plumb::test::writeGridPly;

namespace {

QString q(const std::filesystem::path& p) { return QString::fromStdString(p.string()); }

using test::clickView;
using test::projectToView;

}  // namespace

class GuiInteractionTest : public QObject {
  Q_OBJECT

 private slots:
  void init() {
    test::showMainWindow(window_, QSize(1100, 800));
    if (QTest::currentTestFailed()) return;
    window_->context().recent.clear();
    chosen_.clear();
    requests_.clear();
    // Every file dialog of the application is answered from chosen_ (and recorded).
    setFileChooser([this](FileRequest request, const QString& caption, const QString&,
                          const QString&) {
      requests_.push_back({request, caption});
      return chosen_;
    });
  }
  void cleanup() {
    setFileChooser({});
    window_.reset();
  }

  void opensFilesThroughTheFileMenu() {
    AppContext& app = window_->context();
    const auto dir = test::scratchDir("gui_interaction_open");
    chosen_ = {q(writeGridPly(dir / "red.ply", 51, 255, 0, 0)),
               q(writeGridPly(dir / "blue.ply", 41, 0, 0, 255))};
    QAction* open = menuAction(*window_, "File", "Open...");
    QVERIFY(open);
    QSignalSpy idle(&app.tasks, &TaskManager::idle);
    open->trigger();
    QVERIFY(idle.wait(30000));
    QCOMPARE(requests_.size(), std::size_t{1});
    QVERIFY(requests_[0].first == FileRequest::OpenFiles);
    QCOMPARE(app.log.errorCount(), 0);
    QCOMPARE(app.scene.layers().size(), std::size_t{2});
    // The files load in parallel: the layers come in the order their loads finish.
    std::vector<std::size_t> counts;
    for (const auto& layer : app.scene.layers())
      counts.push_back(static_cast<DatasetLayer*>(layer.get())->dataset().pointCount());
    std::sort(counts.begin(), counts.end());
    QCOMPARE(counts, (std::vector<std::size_t>{41 * 41, 51 * 51}));
    // Both files are in File > Recent files, most recent first.
    QCOMPARE(app.recent.files().size(), 2);
    applyStandardView(app.view.renderer(), StandardView::Top);
    const QImage image = grabView(app.view);
    saveScreenshot(app.view, artefact("menu_open_top.png"));
    QVERIFY(test::countColor(image, QColor(255, 0, 0)) > 500);
    // The grids overlap in z = 0: the one drawn later may cover the other. Alone, blue shows.
    for (const auto& layer : app.scene.layers())
      if (static_cast<DatasetLayer*>(layer.get())->dataset().pointCount() == 51 * 51) {
        layer->setVisible(false);
        app.scene.layerChanged(layer.get());
      }
    QVERIFY(test::countColor(grabView(app.view), QColor(0, 0, 255)) > 500);

    // A canceled dialog (no file chosen) changes nothing.
    chosen_.clear();
    open->trigger();
    QTest::qWait(50);
    QCOMPARE(app.scene.layers().size(), std::size_t{2});
  }

  void opensDroppedFilesAndRecentFiles() {
    AppContext& app = window_->context();
    const auto dir = test::scratchDir("gui_interaction_drop");
    const QString path = q(writeGridPly(dir / "dropped.ply", 31, 0, 255, 0));
    QMimeData mime;
    mime.setUrls({QUrl::fromLocalFile(path)});
    const QPoint at(window_->width() / 2, window_->height() / 2);
    QDragEnterEvent enter(at, Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(window_.get(), &enter);
    QVERIFY(enter.isAccepted());
    QSignalSpy idle(&app.tasks, &TaskManager::idle);
    QDropEvent drop(QPointF(at), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(window_.get(), &drop);
    QVERIFY(drop.isAccepted());
    QVERIFY(idle.wait(30000));
    QCOMPARE(app.log.errorCount(), 0);
    QCOMPARE(app.scene.layers().size(), std::size_t{1});
    QCOMPARE(static_cast<DatasetLayer*>(app.scene.layers()[0].get())->dataset().pointCount(),
             std::size_t{31 * 31});

    // Something that is not a file (a web URL) is not accepted as a drop.
    QMimeData web;
    web.setUrls({QUrl("https://example.org/scan.e57")});
    QDropEvent web_drop(QPointF(at), Qt::CopyAction, &web, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(window_.get(), &web_drop);
    QVERIFY(!web_drop.isAccepted());

    // File > Recent files lists the dropped file; choosing it loads it again.
    QAction* recent_menu = menuAction(*window_, "File", "Recent files");
    QVERIFY(recent_menu && recent_menu->menu());
    QAction* entry = nullptr;
    for (QAction* a : recent_menu->menu()->actions())
      if (a->toolTip() == path) entry = a;
    QVERIFY(entry);
    QCOMPARE(plainLabel(entry->text()), QString("1 dropped.ply"));
    entry->trigger();
    QVERIFY(idle.wait(30000));
    QCOMPARE(app.scene.layers().size(), std::size_t{2});
  }

  void colourModeFromThePropertiesPanelRecoloursInTheBackground() {
    AppContext& app = window_->context();
    const auto dir = test::scratchDir("gui_interaction_style");
    QSignalSpy idle(&app.tasks, &TaskManager::idle);
    window_->openFiles({q(writeGridPly(dir / "red_style.ply", 61, 255, 0, 0))});
    QVERIFY(idle.wait(30000));
    auto* layer = static_cast<DatasetLayer*>(app.scene.layers().at(0).get());
    applyStandardView(app.view.renderer(), StandardView::Top);
    QVERIFY(test::countColor(grabView(app.view), QColor(255, 0, 0)) > 500);
    // Select the layer in the tree: the properties panel shows its point style editor.
    app.layers.setCurrentLayer(layer);
    auto* mode = app.properties.findChild<QComboBox*>("colorMode");
    QVERIFY(mode);
    QVERIFY(mode->isVisibleTo(&app.properties));
    mode->setCurrentIndex(static_cast<int>(PointColorMode::Elevation));
    QCOMPARE(layer->style().mode, PointColorMode::Elevation);
    QTRY_VERIFY_WITH_TIMEOUT(!layer->coloringPending(), 30000);
    // A flat grid in elevation colours: one ramp colour, no red left.
    QCOMPARE(test::countColor(grabView(app.view), QColor(255, 0, 0)), 0);
    mode->setCurrentIndex(static_cast<int>(PointColorMode::Rgb));
    QTRY_VERIFY_WITH_TIMEOUT(!layer->coloringPending(), 30000);
    QVERIFY(test::countColor(grabView(app.view), QColor(255, 0, 0)) > 500);
  }

  void scanColoursAreDistinctAcrossDatasetsWithALegend() {
    AppContext& app = window_->context();
    const auto dir = test::scratchDir("gui_interaction_scan_colours");
    QSignalSpy idle(&app.tasks, &TaskManager::idle);
    // Two single-scan files side by side: "Scan" mode gave both the first palette colour.
    window_->openFiles({q(writeGridPly(dir / "left.ply", 41, 255, 0, 0)),
                        q(writeGridPly(dir / "right.ply", 41, 255, 0, 0, 10.0))});
    QTRY_VERIFY_WITH_TIMEOUT(app.scene.layers().size() == 2 && app.tasks.runningCount() == 0, 30000);
    auto* mode = app.properties.findChild<QComboBox*>("colorMode");
    QVERIFY(mode);
    for (const auto& l : app.scene.layers()) {
      app.layers.setCurrentLayer(l.get());
      mode->setCurrentIndex(static_cast<int>(PointColorMode::Scan));
      QTRY_VERIFY_WITH_TIMEOUT(!static_cast<DatasetLayer*>(l.get())->coloringPending(), 30000);
    }
    applyStandardView(app.view.renderer(), StandardView::Top);
    const QImage image = grabView(app.view);
    saveScreenshot(app.view, artefact("scan_colours_two_datasets.png"));
    const Rgb first = categoryColor(0), second = categoryColor(1);
    const int a = test::countColor(image, QColor(first[0], first[1], first[2]));
    const int b = test::countColor(image, QColor(second[0], second[1], second[2]));
    QVERIFY2(a > 300 && b > 300, qPrintable(QString("%1 and %2 pixels").arg(a).arg(b)));
    // The legend of the selected (second) dataset names its scan and colour.
    const auto rows = app.properties.rows();
    const QString hex = QColor(second[0], second[1], second[2]).name();
    QVERIFY2(std::any_of(rows.begin(), rows.end(), [&](const PropertyRow& r) { return r.second == hex; }),
             qPrintable(hex));
    // RGB is offered for these files, intensity is not (greyed out with the reason).
    auto* items = qobject_cast<QStandardItemModel*>(mode->model());
    QVERIFY(items->item(static_cast<int>(PointColorMode::Rgb))->isEnabled());
    QVERIFY(!items->item(static_cast<int>(PointColorMode::Intensity))->isEnabled());
    QVERIFY(!items->item(static_cast<int>(PointColorMode::Intensity))->toolTip().isEmpty());
    QVERIFY(!items->item(static_cast<int>(PointColorMode::Distance))->isEnabled());
  }

  void ifcTypesHaveTheSameColourInEveryModelWithALegend() {
    AppContext& app = window_->context();
    auto cube = [](std::vector<std::string> types) {
      auto model = std::make_shared<BimModel>();
      for (int i = 0; i < 8; ++i)
        model->mesh.vertices.emplace_back((i & 1) * 4.0, ((i >> 1) & 1) * 4.0, ((i >> 2) & 1) * 4.0);
      model->mesh.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                               {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
      for (const auto& t : types) model->elements.push_back({t, t, ""});
      for (std::size_t k = 0; k < 12; ++k) model->triangle_element.push_back(k % types.size());
      return model;
    };
    // The same types in a different order in the file: walls were blue in one, orange in the other.
    ModelLayer& one = app.scene.addModel(cube({"IfcWall", "IfcDoor", "IfcSlab"}));
    ModelLayer& two = app.scene.addModel(cube({"IfcSlab", "IfcDoor", "IfcWall", "IfcMyProxyType"}));
    auto colourOf = [](const ModelLayer& layer, const QString& type) {
      for (const auto& e : layer.legend())
        if (e.label.startsWith(type + " (")) return e.colour;
      return Rgb8{};
    };
    for (const QString type : {"IfcWall", "IfcDoor", "IfcSlab"}) {
      QCOMPARE(colourOf(one, type), colourOf(two, type));
      QCOMPARE(colourOf(one, type), ifcTypeColor(type.toStdString()));
    }
    QVERIFY(colourOf(one, "IfcWall") != colourOf(one, "IfcDoor"));
    QVERIFY(colourOf(one, "IfcWall") != colourOf(one, "IfcSlab"));
    QCOMPARE(ifcTypeColor("IfcMyProxyType"), ifcTypeColor("IfcMyProxyType"));  // stable, not by order
    QCOMPARE(two.legend().size(), std::size_t{4});
    // The properties panel lists the legend with the colours.
    app.layers.setCurrentLayer(&two);
    const Rgb wall = ifcTypeColor("IfcWall");
    const auto rows = app.properties.rows();
    QVERIFY(std::any_of(rows.begin(), rows.end(), [&](const PropertyRow& r) {
      return r.first.startsWith("IfcWall (") && r.second == QColor(wall[0], wall[1], wall[2]).name();
    }));
  }

  void helpMenuHasGettingStartedOnF1AndAbout() {
    QAction* start = menuAction(*window_, "Help", "Getting started");
    QAction* about = menuAction(*window_, "Help", "About Plumb");
    QVERIFY(start && about);
    QCOMPARE(start->shortcut(), QKeySequence(QKeySequence::HelpContents));  // F1
    start->trigger();
    auto* box = window_->findChild<QMessageBox*>("gettingStarted");
    QVERIFY(box && box->isVisible());
    QVERIFY(!box->isModal());  // the window stays usable beside it
    QVERIFY(box->text().contains("Detect features"));
    QVERIFY(box->text().contains("plumb-cli register"));
    box->close();
    about->trigger();
    auto* info = window_->findChild<QMessageBox*>("aboutPlumb");
    QVERIFY(info && info->isVisible());
    QVERIFY(info->text().contains(PLUMB_UI_VERSION));
    info->close();
  }

  void savesAndOpensProjectsAndScreenshotsThroughTheMenu() {
    AppContext& app = window_->context();
    const auto dir = test::scratchDir("gui_interaction_project");
    const QString data = q(writeGridPly(dir / "grid.ply", 21, 255, 0, 0));
    QSignalSpy idle(&app.tasks, &TaskManager::idle);
    window_->openFiles({data});
    QVERIFY(idle.wait(30000));
    QCOMPARE(app.scene.layers().size(), std::size_t{1});

    // File > Export screenshot: a PNG of the view.
    const QString png = q(dir / "shot.png");
    QFile::remove(png);
    chosen_ = {png};
    menuAction(*window_, "File", "Export screenshot...")->trigger();
    QCOMPARE(requests_.back().first, FileRequest::SaveFile);
    const QImage shot(png);
    QVERIFY(!shot.isNull());
    QVERIFY(test::countNonBackground(shot) > 100);

    // File > Save project, then File > Open project replaces the scene with it.
    const QString project = q(dir / "scene.plumb.json");
    QFile::remove(project);
    QCOMPARE(window_->windowTitle(), QString("Plumb"));
    chosen_ = {project};
    menuAction(*window_, "File", "Save project...")->trigger();
    QVERIFY(QFile::exists(project));
    QCOMPARE(window_->windowTitle(), QString("scene.plumb.json - Plumb"));  // the title names the project
    window_->setWindowTitle("Plumb");
    app.scene.clear();
    QVERIFY(app.scene.layers().empty());
    chosen_ = {project};
    menuAction(*window_, "File", "Open project...")->trigger();
    QCOMPARE(requests_.back().first, FileRequest::OpenFile);
    if (app.scene.layers().empty()) QVERIFY(idle.wait(30000));
    QCOMPARE(app.log.errorCount(), 0);
    QCOMPARE(app.scene.layers().size(), std::size_t{1});
    QCOMPARE(static_cast<DatasetLayer*>(app.scene.layers()[0].get())->dataset().pointCount(),
             std::size_t{21 * 21});
    QCOMPARE(window_->windowTitle(), QString("scene.plumb.json - Plumb"));
  }

  void clickingAFeatureShowsItsProperties() {
    AppContext& app = window_->context();
    // A wall (plane 0, 4321 inliers) with a 2 m window (opening 0) and an eave (segment 0).
    auto features = test::wallWithWindow(4321, true);
    FeatureLayer& layer = app.scene.addFeatures("features", features);
    applyStandardView(app.view.renderer(), StandardView::Front);
    const int white_before = test::countColor(grabView(app.view), Qt::white, 20);  // renders: the projection below uses this frame
    saveScreenshot(app.view, artefact("features_front.png"));

    auto shown = [&app] {
      const auto rows = app.properties.rows();
      return rows.empty() ? QString() : rows.at(0).second;
    };
    clickView(app, projectToView(app, {7.5, 0, 4}));  // on the wall, right of the window
    QCOMPARE(shown(), QString("Plane 0"));
    QVERIFY(!app.scene.reducedDetail());  // a click is no camera move: full detail at once
    QVERIFY(app.properties.rows().size() > 4);
    QCOMPARE(app.properties.rows().at(5).second, QString("4321"));  // inliers
    clickView(app, projectToView(app, {3, -0.01, 1}));  // the window's bottom edge
    QCOMPARE(shown(), QString("Opening 0"));
    QCOMPARE(app.properties.rows().at(1).second, QString("2.000"));  // width
    // The picked feature is highlighted, and only it: its outline drawn thick and white.
    QVERIFY(layer.highlight() && *layer.highlight() == (FeatureRef{FeatureKind::Opening, 0}));
    const QImage highlighted = grabView(app.view);
    saveScreenshot(app.view, artefact("features_picked_opening.png"));
    QVERIFY2(test::countColor(highlighted, Qt::white, 20) > white_before + 100,
             qPrintable(QString("white pixels %1, before %2").arg(test::countColor(highlighted, Qt::white, 20)).arg(white_before)));
    clickView(app, projectToView(app, {5, 0, 7}));  // the middle of the eave
    QCOMPARE(shown(), QString("Segment 0"));
    QCOMPARE(app.properties.rows().at(1).second, QString("10.000"));  // length
    QVERIFY(layer.highlight() && *layer.highlight() == (FeatureRef{FeatureKind::Segment, 0}));
    // A click on empty background leaves the properties as they are.
    clickView(app, projectToView(app, {5, 0, 12}));
    QCOMPARE(shown(), QString("Segment 0"));
  }

  void manualPairsArePickedWithTheMouse() {
    AppContext& app = window_->context();
    // Source: five marker points; target: the same markers moved by a known transform.
    const std::vector<Eigen::Vector3d> markers{
        {0, 0, 0}, {6, 0, 0}, {0, 4, 0}, {0, 0, 3}, {5, 3, 2}};
    const RigidTransform truth = RigidTransform(
        Eigen::AngleAxisd(0.35, Eigen::Vector3d(1, 2, 5).normalized()).toRotationMatrix(),
        Eigen::Vector3d(2.0, -1.0, 0.5));
    PointCloud source_cloud, target_cloud;
    for (const auto& m : markers) {
      source_cloud.positions.push_back(m.cast<float>());
      target_cloud.positions.push_back(truth.apply(m).cast<float>());
    }
    auto& source = app.scene.addDataset(
        std::make_shared<const Dataset>(Dataset::fromCloud(std::move(source_cloud))));
    auto& target = app.scene.addDataset(
        std::make_shared<const Dataset>(Dataset::fromCloud(std::move(target_cloud))));
    for (DatasetLayer* d : {&source, &target}) {
      PointStyle style = d->style();
      style.point_size = 6;
      d->setStyle(style);
    }
    app.registration->setSourceLayer(&source);
    app.registration->setTargetLayer(&target);
    applyStandardView(app.view.renderer(), StandardView::Iso);
    grabView(app.view);
    saveScreenshot(app.view, artefact("manual_markers.png"));

    ManualAlignPanel& manual = *app.manual;
    manual.setPicking(true);
    // Each click lands beside its marker (about 6 px off, outside the 6 px dot): picking snaps
    // to the marker itself, so the fit below is exact.
    const QPoint beside(5, 4);
    for (const auto& m : markers) {
      clickView(app, projectToView(app, m) + beside);                // the source marker...
      clickView(app, projectToView(app, truth.apply(m)) + beside);  // ...then the same on the target
    }
    QCOMPARE(manual.pairCount(), static_cast<int>(markers.size()));
    // Clicks in the view went to the pairs, not to feature picking.
    QVERIFY(manual.align());
    for (int i = 0; i < manual.pairCount(); ++i) QVERIFY(manual.residual(i) < 1e-4);
    const RigidTransform found = layerTransform(source);
    QVERIFY2(RigidTransform::rotationErrorDeg(found, truth) < 1e-3 &&
                 RigidTransform::translationError(found, truth) < 1e-4,
             qPrintable(QString("%1 deg %2 m")
                            .arg(RigidTransform::rotationErrorDeg(found, truth))
                            .arg(RigidTransform::translationError(found, truth))));
    manual.setPicking(false);
  }

  // Every budget is drawn exactly: one scan draws the whole budget, two scans share it by size
  // without exceeding it (the share was computed in doubles and came one point short for
  // some budgets, which made draggingTheCameraUsesLevelOfDetail fail now and then).
  void movingSubsetsAreExactlyTheBudget() {
    Scene& scene = window_->context().scene;
    auto grid = [](int n) {
      PointCloud cloud;
      for (int i = 0; i < n; ++i) cloud.positions.emplace_back(static_cast<float>(i % 1000), static_cast<float>(i / 1000), 0.f);
      return std::make_shared<const Dataset>(Dataset::fromCloud(std::move(cloud)));
    };
    scene.addDataset(grid(600000));
    scene.setMovingDetail(true);
    for (std::size_t budget = 100000; budget < 130000; budget += 7) {
      scene.setLodBudget(budget);
      QCOMPARE(scene.drawnPointCount(), budget);
    }
    scene.addDataset(grid(200000));
    scene.setMovingDetail(true);  // the view's LOD controller reset still detail for the new layer
    for (std::size_t budget = 100000; budget < 130000; budget += 7) {
      scene.setLodBudget(budget);
      const std::size_t drawn = scene.drawnPointCount();
      QVERIFY2(drawn <= budget && drawn + 2 >= budget, qPrintable(QString("%1 of %2").arg(drawn).arg(budget)));
    }
    scene.setMovingDetail(false);
  }

  void draggingTheCameraUsesLevelOfDetail() {
    AppContext& app = window_->context();
    PointCloud cloud;  // 600,000 points: more than the initial budget
    for (int i = 0; i < 600000; ++i)
      cloud.positions.emplace_back(static_cast<float>(i % 1000) * 0.02f,
                                   static_cast<float>(i / 1000) * 0.02f, 0.0f);
    app.scene.addDataset(std::make_shared<const Dataset>(Dataset::fromCloud(std::move(cloud))));
    resetCamera(app.view.renderer());
    grabView(app.view);
    // Still: the whole cloud or the still budget's subset (see stillFrameKeepsToItsBudget).
    QTRY_VERIFY_WITH_TIMEOUT(lodController().settled(), 10000);
    QVERIFY(app.scene.drawnPointCount() > LodBudget().params().min_points);

    const QPoint centre(app.view.width() / 2, app.view.height() / 2);
    QSignalSpy frames(&app.view, &VtkViewWidget::frameRendered);
    QTest::mousePress(&app.view, Qt::LeftButton, Qt::NoModifier, centre);
    for (int i = 1; i <= 6; ++i) {
      QTest::mouseMove(&app.view, centre + QPoint(12 * i, 4 * i));
      QTest::qWait(30);
      app.view.renderNow();
    }
    QVERIFY(app.scene.reducedDetail());
    const std::size_t moving = app.scene.drawnPointCount();
    QVERIFY2(moving < 600000 && moving >= LodBudget().params().min_points,
             qPrintable(QString::number(moving)));
    QCOMPARE(moving, std::min<std::size_t>(600000, app.scene.lodBudget()));
    QTest::mouseRelease(&app.view, Qt::LeftButton, Qt::NoModifier, centre + QPoint(72, 24));
    QVERIFY(frames.size() >= 6);
    // Still again after the settle delay: the whole cloud, or the still budget's subset when
    // the OpenGL cannot draw it within the still frame's target.
    LodController& lod = lodController();
    QTRY_VERIFY_WITH_TIMEOUT(lod.settled(), 10000);
    const std::size_t still = app.scene.drawnPointCount();
    const std::size_t expected = std::min<std::size_t>(600000, lod.stillBudget().points());
    QVERIFY2(still + 1 >= expected && still <= expected,
             qPrintable(QString("%1 drawn, still budget %2").arg(still).arg(expected)));
  }

  void stillFrameKeepsToItsBudget() {
    // 5,000,000 points: seconds per full frame under software OpenGL (llvmpipe), the still
    // frame must stay near its target and say in the status bar that it shows a subset.
    AppContext& app = window_->context();
    constexpr std::size_t kPoints = 5'000'000;
    constexpr double kPointSize = 4.0;
    PointCloud cloud;
    cloud.positions.reserve(kPoints);
    for (std::size_t i = 0; i < kPoints; ++i)
      cloud.positions.emplace_back(static_cast<float>(i % 2500) * 0.01f,
                                   static_cast<float>(i / 2500) * 0.01f,
                                   static_cast<float>(i % 7) * 0.05f);
    LodController& lod = lodController();
    QSignalSpy frames(&lod, &LodController::stillFrameDrawn);
    auto& layer =
        app.scene.addDataset(std::make_shared<const Dataset>(Dataset::fromCloud(std::move(cloud))));
    // Large points (more fill work per point): 5 M points take 1-2 s per frame on llvmpipe.
    PointStyle style = layer.style();
    style.point_size = kPointSize;
    layer.setStyle(style);
    resetCamera(app.view.renderer());
    QCOMPARE(lod.totalPointCount(), kPoints);
    // Loading draws the still subset (no full frame on the first paint either), then larger
    // ones while frames are well under target.
    // Behaviour, not a wall-clock budget (frame times are measured by bench_ui): the loaded
    // view settles on a subset, never on the 5 M points that take 1-2 s per frame here.
    QTRY_VERIFY_WITH_TIMEOUT(frames.size() > 0 && lod.settled(), 20000);
    for (const auto& f : frames) qInfo("still frame after loading: %.0f ms", f[0].toDouble());
    QVERIFY2(app.scene.reducedDetail() && app.scene.drawnPointCount() < kPoints,
             qPrintable(QString::number(app.scene.drawnPointCount())));

    // A camera drag, then the still frame: within its budget, a subset, reported.
    const QPoint centre(app.view.width() / 2, app.view.height() / 2);
    QTest::mousePress(&app.view, Qt::LeftButton, Qt::NoModifier, centre);
    for (int i = 1; i <= 4; ++i) {
      QTest::mouseMove(&app.view, centre + QPoint(10 * i, 5 * i));
      QTest::qWait(30);
      app.view.renderNow();
    }
    QVERIFY(lod.moving());
    QTest::mouseRelease(&app.view, Qt::LeftButton, Qt::NoModifier, centre + QPoint(40, 20));
    frames.clear();
    QTRY_VERIFY_WITH_TIMEOUT(frames.size() > 0 && lod.settled(), 20000);
    for (const auto& f : frames) qInfo("still frame after a drag: %.0f ms", f[0].toDouble());
    const std::size_t drawn = app.scene.drawnPointCount();
    QVERIFY2(app.scene.reducedDetail() && drawn < kPoints && drawn >= 20000,
             qPrintable(QString::number(drawn)));
    auto* status = window_->findChild<QLabel*>("detailLabel");
    QVERIFY(status);
    QCOMPARE(status->text(), detailStatusText(drawn, kPoints));
    QVERIFY2(status->text().startsWith("Showing ") && status->text().endsWith(" points"),
             qPrintable(status->text()));
    qInfo("still frames after the drag: %lld, last %.0f ms, %s",
          static_cast<long long>(frames.size()), frames.last()[0].toDouble(),
          qPrintable(status->text()));

    // View > Full detail when still: every point, however long the frame takes.
    QAction* full = menuAction(*window_, "View", "Full detail when still (may be slow)");
    QVERIFY(full && full->isCheckable() && !full->isChecked());
    frames.clear();
    full->trigger();
    QVERIFY(lod.fullDetailWhenStill());
    QTRY_VERIFY_WITH_TIMEOUT(frames.size() > 0, 30000);
    QCOMPARE(app.scene.drawnPointCount(), kPoints);
    QVERIFY(!app.scene.reducedDetail());
    QVERIFY(status->text().isEmpty());
    qInfo("forced full detail frame: %.0f ms for %zu points", frames.last()[0].toDouble(), kPoints);
    // Off again: the next still frame is the budget's subset again.
    full->trigger();
    QVERIFY(!lod.fullDetailWhenStill());
    QVERIFY(app.scene.reducedDetail() && app.scene.drawnPointCount() < kPoints);
    QVERIFY(!status->text().isEmpty());
  }

  void lodBudgetConvergesToTheTargetFrameTime() {
    // Frame time model t = 8 ms + 0.5 us per point: the target of 50 ms is met at 84,000.
    LodBudget::Params p;
    p.target_ms = 50.0;
    LodBudget budget(p);
    auto frame_ms = [](std::size_t n) { return 8.0 + 0.5e-3 * static_cast<double>(n); };
    for (int i = 0; i < 40; ++i) budget.addFrame(budget.points(), frame_ms(budget.points()));
    QVERIFY2(std::abs(frame_ms(budget.points()) - 50.0) < 50.0 * 0.15,
             qPrintable(QString::number(budget.points())));
    // A fast GPU (1 ns per point) grows the budget to its maximum; a hopeless one (fixed cost
    // above the target) shrinks it to the minimum.
    LodBudget fast(p), slow(p);
    for (int i = 0; i < 40; ++i) {
      fast.addFrame(fast.points(), 2.0 + 1e-6 * static_cast<double>(fast.points()));
      slow.addFrame(slow.points(), 80.0 + 1e-6 * static_cast<double>(slow.points()));
    }
    QCOMPARE(fast.points(), p.max_points);
    QCOMPARE(slow.points(), p.min_points);
    // Jitter inside the dead band does not move the budget.
    LodBudget steady(p);
    const std::size_t before = steady.points();
    QVERIFY(!steady.addFrame(before, 52.0));
    QCOMPARE(steady.points(), before);
  }

 private:
  LodController& lodController() {
    auto* lod = window_->findChild<LodController*>();
    if (!lod) qFatal("the main window has no LodController");
    return *lod;
  }
  QString artefact(const QString& name) {
    static const auto dir = test::scratchDir("gui_interaction");
    return QString::fromStdString((dir / name.toStdString()).string());
  }
  std::unique_ptr<MainWindow> window_;
  QStringList chosen_;
  std::vector<std::pair<FileRequest, QString>> requests_;
};

int main(int argc, char** argv) { return test::runGuiTest<GuiInteractionTest>(argc, argv, "PlumbTestsInteraction"); }

#include "test_gui_interaction.moc"
