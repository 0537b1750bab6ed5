// GUI tests of the Plumb desktop application: open files through the main window, check the
// layer tree and properties, grab the framebuffer and check the image shows the layers in
// their known colours. Screenshots are saved under <build>/test-artifacts/gui_app/.
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QScrollArea>
#include <QSpinBox>
#include <QSignalSpy>
#include <QTest>
#include <QTreeWidget>

#include <vtkActor.h>
#include <vtkMapper.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>
#include <vtkProp.h>


#include "gui/feature_fixtures.hpp"
#include "support/damaged_models.hpp"
#include "gui/grid_ply.hpp"
#include "gui/image_checks.hpp"
#include "gui/open_window.hpp"
#include "support/test_support.hpp"
#include "ui/layers/dataset_layer.hpp"
#include "ui/layers/feature_layer.hpp"
#include "ui/layers/model_layer.hpp"
#include "ui/layers/point_coloring.hpp"
#include "ui/layers/scan_layer.hpp"
#include "ui/layers/scene.hpp"
#include "ui/main_window.hpp"
#include "ui/panels/layer_tree_panel.hpp"
#include "ui/panels/log_panel.hpp"
#include "ui/panels/param_panel.hpp"
#include "ui/registration/param_groups_box.hpp"
#include "ui/panels/properties_panel.hpp"
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
using plumb::test::writeGridPly;

namespace {

enum class Method { Auto, Planes, Icp };
struct DemoParams {
  double threshold = 0.05;
  int iterations = 30;
  bool refine = true;
  Method method = Method::Planes;
  static const ParamSchema<DemoParams>& schema() {
    static const auto s = ParamSchema<DemoParams>("demo")
                              .real(&DemoParams::threshold, "threshold", "Threshold", "m", 0.001,
                                    1.0, "distance threshold")
                              .integer(&DemoParams::iterations, "iterations", "Iterations", "",
                                       1, 500, "iterations", true)
                              .boolean(&DemoParams::refine, "refine", "Refine", "ICP refine")
                              .choice(&DemoParams::method, "method", "Method",
                                      {"auto", "planes", "icp"}, "method");
    return s;
  }
};

}  // namespace

class GuiAppTest : public QObject {
  Q_OBJECT

 private slots:
  void init() {
    test::showMainWindow(window_, QSize(1100, 800));
    if (QTest::currentTestFailed()) return;
  }
  void cleanup() { window_.reset(); }

  void opensRealE57AndShowsIt() {
    AppContext& app = window_->context();
    QSignalSpy idle(&app.tasks, &TaskManager::idle);
    window_->openFiles({QString::fromStdString(test::sharedData("e57/bunnyFloat.e57").string())});
    QVERIFY(idle.wait(30000));
    QCOMPARE(app.log.errorCount(), 0);
    QCOMPARE(app.scene.layers().size(), std::size_t{1});
    auto* dataset = dynamic_cast<DatasetLayer*>(app.scene.layers()[0].get());
    QVERIFY(dataset);
    QCOMPARE(dataset->scans().size(), std::size_t{1});
    // shared/data/README.md: the libe57.org bunny has 30,571 points.
    QCOMPARE(dataset->dataset().pointCount(), std::size_t{30571});
    // Layer tree: the dataset row with its scan row below, both checked.
    QTreeWidgetItem* row = app.layers.itemOf(dataset);
    QVERIFY(row);
    QCOMPARE(row->text(0), QString("bunnyFloat.e57"));
    QCOMPARE(row->childCount(), 1);
    QCOMPARE(row->checkState(0), Qt::Checked);

    const QImage image = grabView(app.view);
    saveScreenshot(app.view, artefact("bunny.png"));
    QVERIFY(image.width() > 100 && image.height() > 100);
    // No RGB in the bunny: coloured by elevation (viridis), far from the grey background.
    const int drawn = countNonBackground(image);
    QVERIFY2(drawn > image.width() * image.height() / 100, qPrintable(QString::number(drawn)));

    // Hiding the dataset through the tree leaves only background.
    row->setCheckState(0, Qt::Unchecked);
    QVERIFY(!dataset->visible());
    QCOMPARE(countNonBackground(grabView(app.view)), 0);
  }

  void colorsPointsByRgbAndScan() {
    AppContext& app = window_->context();
    const auto dir = test::scratchDir("gui_app_rgb");
    QSignalSpy idle(&app.tasks, &TaskManager::idle);
    window_->openFiles(
        {QString::fromStdString(writeGridPly(dir / "red_grid.ply", 101, 255, 0, 0).string())});
    QVERIFY(idle.wait(30000));
    QCOMPARE(app.log.errorCount(), 0);
    QCOMPARE(app.scene.layers().size(), std::size_t{1});
    applyStandardView(app.view.renderer(), StandardView::Top);
    QImage image = grabView(app.view);
    saveScreenshot(app.view, artefact("red_grid_rgb.png"));
    const int red = countColor(image, QColor(255, 0, 0));
    QVERIFY2(red > 2000, qPrintable(QString::number(red)));

    // Colour by scan: the first category colour replaces red.
    auto* dataset = static_cast<DatasetLayer*>(app.scene.layers()[0].get());
    PointStyle style = dataset->style();
    style.mode = PointColorMode::Scan;
    dataset->setStyle(style);
    image = grabView(app.view);
    saveScreenshot(app.view, artefact("red_grid_scan.png"));
    const Rgb c = categoryColor(0);
    QCOMPARE(countColor(image, QColor(255, 0, 0)), 0);
    QVERIFY(countColor(image, QColor(c[0], c[1], c[2])) > 2000);
  }

  void levelOfDetailShowsTheSubsetWhileMoving() {
    AppContext& app = window_->context();
    // 200,000 points with a 10,000 point budget: the reduced actor draws 10,000.
    PointCloud cloud;
    for (int i = 0; i < 200000; ++i)
      cloud.positions.emplace_back(static_cast<float>(i % 500) * 0.04f,
                                   static_cast<float>(i / 500) * 0.05f, 0.0f);
    auto data = std::make_shared<const Dataset>(Dataset::fromCloud(std::move(cloud)));
    auto layer = std::make_unique<DatasetLayer>(data, Eigen::Vector3d::Zero(), 10000);
    ScanLayer* scan = layer->scans().at(0);
    QCOMPARE(scan->lodPointCount(), std::size_t{10000});
    auto props = scan->props();
    QCOMPARE(props.size(), std::size_t{2});
    QVERIFY(props[0]->GetVisibility() && !props[1]->GetVisibility());
    scan->setReducedDetail(true);
    QVERIFY(!props[0]->GetVisibility() && props[1]->GetVisibility());
    scan->setReducedDetail(false);
    QVERIFY(props[0]->GetVisibility() && !props[1]->GetVisibility());
    QCOMPARE(scan->drawnPointCount(), std::size_t{200000});

    // A still subset: both subsets are prefixes of one random order of the points, vertex i
    // of either actor is cloud point originalIndices()[i] (distinct, spread over the cloud).
    scan->setStillPointCount(50000);
    QCOMPARE(scan->drawnPointCount(), std::size_t{50000});
    auto input = [&props](std::size_t i) {
      return vtkPolyData::SafeDownCast(static_cast<vtkActor*>(props[i])->GetMapper()->GetInput());
    };
    vtkPolyData* still = input(0);
    vtkPolyData* moving = input(1);
    QVERIFY(still && moving);
    QCOMPARE(still->GetNumberOfPoints(), vtkIdType{50000});
    QCOMPARE(still->GetNumberOfVerts(), vtkIdType{1});
    QCOMPARE(moving->GetNumberOfPoints(), vtkIdType{10000});
    const PointCloud& source = data->scans[0].cloud;
    std::vector<bool> seen(source.size(), false);
    std::size_t upper_half = 0;
    const std::vector<std::uint32_t> original = scan->originalIndices();
    QCOMPARE(original.size(), source.size());
    for (vtkIdType i = 0; i < still->GetNumberOfPoints(); ++i) {
      const std::size_t j = original[static_cast<std::size_t>(i)];
      QVERIFY(j < source.size() && !seen[j]);
      seen[j] = true;
      upper_half += j >= source.size() / 2;
      double p[3];
      (i < 10000 ? moving : still)->GetPoint(i, p);
      QCOMPARE(p[0], static_cast<double>(source.positions[j].x()));
      QCOMPARE(p[1], static_cast<double>(source.positions[j].y()));
    }
    QVERIFY2(upper_half > 24000 && upper_half < 26000, qPrintable(QString::number(upper_half)));
    // Colours (cloud order in) follow the same order: vertex i has point original[i]'s colour.
    std::vector<float> distances(source.size());
    for (std::size_t i = 0; i < distances.size(); ++i) distances[i] = float(i % 1000) / 1000.0f;
    std::vector<Rgb> expected(source.size());
    fillDistanceColors(distances, DistanceScale{1.0, false}, expected);
    scan->setDistances(distances, DistanceScale{1.0, false});
    PointStyle by_distance;
    by_distance.mode = PointColorMode::Distance;
    scan->setStyle(by_distance, 0.0, 1.0);
    auto* colors = vtkUnsignedCharArray::SafeDownCast(still->GetPointData()->GetScalars());
    QVERIFY(colors && colors->GetNumberOfComponents() == 4);
    for (vtkIdType i = 0; i < still->GetNumberOfPoints(); ++i)
      for (int c = 0; c < 3; ++c)
        QCOMPARE(colors->GetValue(4 * i + c), expected[original[static_cast<std::size_t>(i)]][c]);
    // Moving <-> still toggles the actors and keeps both subsets (no rebuild).
    scan->setReducedDetail(true);
    QVERIFY(!props[0]->GetVisibility() && props[1]->GetVisibility());
    QCOMPARE(scan->drawnPointCount(), std::size_t{10000});
    scan->setReducedDetail(false);
    QVERIFY(input(0) == still && input(1) == moving);
    scan->setStillPointCount(200000);  // full detail again
    QCOMPARE(scan->drawnPointCount(), std::size_t{200000});
    (void)app;
  }

  void featureOverlayIsDrawnAndPicked() {
    AppContext& app = window_->context();
    auto features = test::wallWithWindow(1234, false);
    app.scene.addFeatures("features", features);
    QCOMPARE(app.layers.topLevelItemCount(), 1);
    applyStandardView(app.view.renderer(), StandardView::Front);
    const QImage image = grabView(app.view);
    saveScreenshot(app.view, artefact("features_front.png"));
    QVERIFY(countColor(image, QColor(255, 64, 200), 12) > 50);  // the opening's rectangle

    // A click in the middle of the view hits the wall (x = 5 m is right of the window).
    const int w = image.width(), h = image.height();
    auto hit = app.scene.pick(w / 2 + w / 10, h / 2);
    QVERIFY(hit.has_value());
    QCOMPARE(hit->rows.at(0).second, QString("Plane 0"));
    // Through the view's click signal, the properties panel shows the feature.
    emit app.view.clicked(w / 2 + w / 10, h / 2);
    QCOMPARE(app.properties.rows().at(0).second, QString("Plane 0"));
  }

  void modelIsShadedWithEdgesAndTransparency() {
    AppContext& app = window_->context();
    auto model = std::make_shared<BimModel>();
    // A 4 m cube (12 triangles), element type IfcWall.
    for (int i = 0; i < 8; ++i)
      model->mesh.vertices.emplace_back((i & 1) * 4.0, ((i >> 1) & 1) * 4.0, ((i >> 2) & 1) * 4.0);
    model->mesh.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                             {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
    model->elements.push_back({"IfcWall", "wall", ""});
    model->triangle_element.assign(12, 0);
    ModelLayer& layer = app.scene.addModel(model);
    resetCamera(app.view.renderer());
    const QImage opaque = grabView(app.view);
    saveScreenshot(app.view, artefact("model_cube.png"));
    QVERIFY(countNonBackground(opaque) > opaque.width() * opaque.height() / 50);
    layer.setStyle({true, 0.3});
    const QImage faint = grabView(app.view);
    saveScreenshot(app.view, artefact("model_cube_transparent_edges.png"));
    QVERIFY(countNonBackground(faint) < countNonBackground(opaque));
  }

  void paramPanelIsGeneratedFromTheSchema() {
    DemoParams params;
    std::unique_ptr<ParamPanel> panel(makeParamPanel(DemoParams::schema(), params));
    auto* threshold = qobject_cast<QDoubleSpinBox*>(panel->editor("threshold"));
    auto* iterations = qobject_cast<QSpinBox*>(panel->editor("iterations"));
    auto* refine = qobject_cast<QCheckBox*>(panel->editor("refine"));
    auto* method = qobject_cast<QComboBox*>(panel->editor("method"));
    QVERIFY(threshold && iterations && refine && method);
    // Defaults, units, ranges and tooltips come from the schema.
    QCOMPARE(threshold->value(), 0.05);
    QCOMPARE(threshold->suffix(), QString(" m"));
    QCOMPARE(threshold->maximum(), 1.0);
    QCOMPARE(threshold->toolTip(), QString("distance threshold"));
    QCOMPARE(iterations->value(), 30);
    QCOMPARE(method->currentText(), QString("planes"));
    // Edits reach the struct.
    threshold->setValue(0.2);
    iterations->setValue(12);
    refine->setChecked(false);
    method->setCurrentIndex(2);
    QCOMPARE(params.threshold, 0.2);
    QCOMPARE(params.iterations, 12);
    QVERIFY(!params.refine);
    QVERIFY(params.method == Method::Icp);
    threshold->setValue(5.0);  // clamped to the schema's range
    QCOMPARE(params.threshold, 1.0);
  }

  // Issue 14: the source's orientation reaches the Registration dock from the schema alone.
  void registrationDockOffersTheSourceOrientation() {
    PipelineParams params;
    ParamGroupsBox box(params);
    int page = -1;
    for (int i = 0; i < box.count(); ++i)
      if (box.itemText(i) == "Source orientation") page = i;
    QVERIFY(page >= 0);
    auto* scroll = qobject_cast<QScrollArea*>(box.widget(page));
    QVERIFY(scroll);
    auto* panel = qobject_cast<ParamPanel*>(scroll->widget());
    QVERIFY(panel);
    auto* source = qobject_cast<QComboBox*>(panel->editor("source"));
    QVERIFY(source);
    QCOMPARE(source->count(), 4);
    QCOMPARE(source->currentText(), QString("auto"));
    source->setCurrentIndex(source->findText("y-up"));
    QVERIFY(params.orientation.source == SourceOrientation::YUp);
    box.enableFor(RegistrationMethod::Icp);  // ICP searches nothing: no orientation
    QVERIFY(!box.isItemEnabled(page));
    box.enableFor(RegistrationMethod::Planes);
    QVERIFY(box.isItemEnabled(page));
  }

  void loadErrorIsLoggedWithTheFileName() {
    AppContext& app = window_->context();
    QSignalSpy idle(&app.tasks, &TaskManager::idle);
    QSignalSpy logged(&app.log, &LogPanel::logged);
    window_->openFiles({"/nonexistent/plumb-missing.las"});
    QVERIFY(idle.wait(30000));
    QCOMPARE(app.log.errorCount(), 1);
    QVERIFY(app.scene.layers().empty());
    bool named = false;
    for (const auto& args : logged)
      named |= args.at(1).toString().contains("plumb-missing.las");
    QVERIFY(named);
  }

  void damagedIfcIsLoggedAndTheAppCarriesOn() {
    // duplex.ifc without entity #8961 crashes assimp (SIGSEGV): the import helper dies, the
    // application logs the error naming the file and still opens the next model.
    AppContext& app = window_->context();
    const auto dir = test::scratchDir("gui_app_damaged_ifc");
    const auto ifc = test::duplexWithout(dir, "#8961=", "duplex_no_8961.ifc");
    test::writeAll(dir / "tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\no tri\nf 1 2 3\n");
    QSignalSpy idle(&app.tasks, &TaskManager::idle);
    QSignalSpy logged(&app.log, &LogPanel::logged);
    window_->openFiles({QString::fromStdString(ifc.string())});
    QVERIFY(idle.wait(60000));
    QCOMPARE(app.log.errorCount(), 1);
    QVERIFY(app.scene.layers().empty());
    bool named = false;
    for (const auto& args : logged)
      named |= args.at(1).toString().contains("duplex_no_8961.ifc") && args.at(1).toString().contains("assimp crashed");
    QVERIFY2(named, qPrintable(app.log.toPlainText()));
    window_->openFiles({QString::fromStdString((dir / "tri.obj").string())});
    QVERIFY(idle.wait(60000));
    QCOMPARE(app.scene.layers().size(), std::size_t{1});
    QCOMPARE(app.log.errorCount(), 1);
  }

 private:
  QString artefact(const QString& name) {
    static const auto dir = test::scratchDir("gui_app");
    return QString::fromStdString((dir / name.toStdString()).string());
  }
  std::unique_ptr<MainWindow> window_;
};

int main(int argc, char** argv) { return test::runGuiTest<GuiAppTest>(argc, argv); }

#include "test_gui_app.moc"
