// Framing on robust extents (issue 17): a few returns 150 m away must not make the default view,
// Reset camera or Zoom to layer frame a speck; the Properties extent is the exact one
// `plumb-cli info` reports, not the box of rotated scan boxes.
#include <QSignalSpy>
#include <QTest>

#include <vtkCamera.h>
#include <vtkRenderer.h>

#include <fstream>

#include "gui/image_checks.hpp"
#include "gui/menu_actions.hpp"
#include "gui/open_window.hpp"
#include "support/test_support.hpp"
#include "ui/layers/dataset_layer.hpp"
#include "ui/layers/scene.hpp"
#include "ui/main_window.hpp"
#include "ui/panels/layer_tree_panel.hpp"
#include "ui/tasks/task_manager.hpp"
#include "ui/view/screenshot.hpp"
#include "ui/view/standard_view.hpp"
#include "ui/view/vtk_view_widget.hpp"

using namespace plumb;
using namespace plumb::ui;

namespace {
/// A red 6 x 6 m floor (31 x 31 points) and three green far returns 150 m away.
QString floorWithFarReturns(const std::filesystem::path& path) {
  std::ofstream out(path);
  out << "ply\nformat ascii 1.0\nelement vertex " << 31 * 31 + 3
      << "\nproperty float x\nproperty float y\nproperty float z\n"
         "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n";
  for (int i = 0; i < 31; ++i)
    for (int j = 0; j < 31; ++j) out << i * 0.2 << " " << j * 0.2 << " 0 255 0 0\n";
  for (int k = 0; k < 3; ++k) out << 150 + k << " " << -150 << " 20 0 255 0\n";
  return QString::fromStdString(path.string());
}
}  // namespace

class GuiFramingTest : public QObject {
  Q_OBJECT

 private slots:
  void viewsFrameTheDataNotItsOutliers() {
    std::unique_ptr<MainWindow> window;
    const auto dir = test::scratchDir("gui_framing");
    test::openWindowWithFiles(window, {floorWithFarReturns(dir / "floor.ply")});
    if (QTest::currentTestFailed()) return;
    AppContext& app = window->context();
    // The floor spans most of the view at the first view after loading ...
    const int framed = test::hueSpan(grabView(app.view), 0);
    QVERIFY2(framed > 300, qPrintable(QString("floor span after loading: %1 px").arg(framed)));
    // ... while fitting every prop, far returns included, makes it a speck.
    applyStandardView(app.view.renderer(), StandardView::Iso);
    const int all_props = test::hueSpan(grabView(app.view), 0);
    qInfo("floor span: %d px framed, %d px fitted to every prop", framed, all_props);
    QVERIFY2(all_props < framed / 10, qPrintable(QString("fitted to everything: %1 px").arg(all_props)));
    // View > Reset camera and View > Zoom to layer frame the floor again.
    test::menuAction(*window, "View", "Reset camera")->trigger();
    QCOMPARE(test::hueSpan(grabView(app.view), 0), framed);
    applyStandardView(app.view.renderer(), StandardView::Iso);
    app.layers.setCurrentLayer(app.scene.layers()[0].get());
    test::menuAction(*window, "View", "Zoom to layer")->trigger();
    QVERIFY(test::hueSpan(grabView(app.view), 0) > framed / 2);
    // The exact bounds (Properties extent) still hold the far returns.
    QVERIFY(app.scene.layers()[0]->bounds().size().x() > 150.0);
  }

  void thePropertiesExtentIsTheExactOneOfTheDataset() {
    auto data = std::make_shared<Dataset>();
    data->scans.push_back({});
    for (int i = 0; i < 720; ++i) {  // a circle of radius 5 m: its scan box is 10 x 10 m
      const double a = i * M_PI / 360.0;
      data->scans[0].cloud.positions.push_back(Eigen::Vector3f(5.0f * float(std::cos(a)), 5.0f * float(std::sin(a)), 0.0f));
    }
    data->scans[0].pose = RigidTransform::fromYaw(M_PI / 4, {0, 0, 0});  // turned 45 deg
    DatasetLayer layer(data, Eigen::Vector3d::Zero());
    const Bounds exact = data->bounds();
    QVERIFY(std::abs(exact.size().x() - 10.0) < 1e-3);
    // The box of the turned scan box would be 14.1 m wide: the Properties extent is the exact 10 m.
    QVERIFY(std::abs(layer.bounds().size().x() - exact.size().x()) < 1e-6);
    QVERIFY(std::abs(layer.bounds().size().y() - exact.size().y()) < 1e-6);
    QVERIFY(layer.framingBounds().size().x() < 11.1);
  }
};

int main(int argc, char** argv) { return test::runGuiTest<GuiFramingTest>(argc, argv, "PlumbTestsFraming"); }

#include "test_gui_framing.moc"
