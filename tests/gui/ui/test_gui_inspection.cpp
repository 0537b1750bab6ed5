// Inspection tools (issue 17): View > Measure shows a clicked point's coordinates, then the
// distance to a second one (slope, horizontal, height difference) equal to the true one within
// the point spacing; View > Orthographic projection switches to a parallel projection.
#include <QAction>
#include <QComboBox>
#include <QDockWidget>
#include <QLabel>
#include <QPushButton>
#include <QTest>

#include <vtkCamera.h>
#include <vtkRenderer.h>

#include "gui/image_checks.hpp"
#include "gui/menu_actions.hpp"
#include "gui/open_window.hpp"
#include "gui/view_clicks.hpp"
#include "support/test_support.hpp"
#include "ui/actions/inspection_reactions.hpp"
#include "ui/inspection/clip_panel.hpp"
#include "ui/panels/layer_tree_panel.hpp"
#include "ui/panels/log_panel.hpp"
#include "ui/inspection/measure_tool.hpp"
#include "ui/layers/dataset_layer.hpp"
#include "ui/layers/scene.hpp"
#include "ui/main_window.hpp"
#include "ui/panels/properties_panel.hpp"
#include "ui/view/scene_framing.hpp"
#include "ui/view/screenshot.hpp"

using namespace plumb;
using namespace plumb::ui;

namespace {
constexpr double kSpacing = 0.1;

/// Whether the camera looks along world axis `axis` (either way).
bool lookingAlong(ui::AppContext& app, int axis) {
  const double* d = app.view.renderer()->GetActiveCamera()->GetDirectionOfProjection();
  return std::abs(std::abs(d[axis]) - 1.0) < 1e-6;
}

/// A red 10 x 10 m floor at 0.1 m spacing, at national-grid coordinates, and a green 1 x 1 m
/// block top 1.5 m above it at (8..9, 8..9) (11 x 11 points).
std::shared_ptr<const Dataset> floorAndBlock(const Eigen::Vector3d& offset) {
  PointCloud c;
  c.offset = offset;
  for (int i = 0; i <= 100; ++i)
    for (int j = 0; j <= 100; ++j) {
      const bool block = i >= 80 && i <= 90 && j >= 80 && j <= 90;
      c.positions.push_back(Eigen::Vector3f(float(kSpacing * i), float(kSpacing * j), block ? 1.5f : 0.0f));
      c.colors.push_back(block ? std::array<std::uint8_t, 3>{0, 255, 0} : std::array<std::uint8_t, 3>{255, 0, 0});
    }
  return std::make_shared<const Dataset>(Dataset::fromCloud(std::move(c)));
}

const Eigen::Vector3d grid(651000.0, 6860000.0, 40.0);  ///< where the floor's corner is

/// A main window showing floorAndBlock(grid).
void showFloor(std::unique_ptr<MainWindow>& window) {
  test::showMainWindow(window, QSize(1100, 800));
  if (!QTest::currentTestFailed()) window->context().scene.addDataset(floorAndBlock(grid));
}

QString row(const std::vector<PropertyRow>& rows, const QString& key) {
  for (const auto& [k, v] : rows)
    if (k == key) return v;
  return {};
}
}  // namespace

class GuiInspectionTest : public QObject {
  Q_OBJECT

 private slots:
  void measuresPointsAndDistancesWithTheMouse() {
    std::unique_ptr<MainWindow> window;
    showFloor(window);
    if (QTest::currentTestFailed()) return;
    AppContext& app = window->context();
    frameScene(app.scene, app.view, StandardView::Top);
    grabView(app.view);

    QAction* measure = test::menuAction(*window, "View", "Measure point / distance");
    QVERIFY(measure && measure->isCheckable());
    measure->trigger();
    QVERIFY(app.measure->active());
    // First click: the point's coordinates, in the national grid.
    const Eigen::Vector3d a = grid + Eigen::Vector3d(2.0, 3.0, 0.0);
    test::clickView(app, test::projectToView(app, a));
    auto rows = app.properties.rows();
    QVERIFY2(std::abs(row(rows, "X (m)").toDouble() - a.x()) <= kSpacing, qPrintable(row(rows, "X (m)")));
    QVERIFY2(std::abs(row(rows, "Y (m)").toDouble() - a.y()) <= kSpacing, qPrintable(row(rows, "Y (m)")));
    QCOMPARE(row(rows, "Z (m)"), QString("40.000"));
    // Second click, on the block top: the distance, within the point spacing of the truth.
    const Eigen::Vector3d b = grid + Eigen::Vector3d(8.5, 8.5, 1.5);
    test::clickView(app, test::projectToView(app, b));
    QVERIFY(app.measure->last());
    const Measurement& m = *app.measure->last();
    QVERIFY2(std::abs(m.slope - (b - a).norm()) <= std::sqrt(2.0) * kSpacing,
             qPrintable(QString("%1 against %2").arg(m.slope).arg((b - a).norm())));
    QVERIFY(std::abs(m.horizontal - (b - a).head<2>().norm()) <= std::sqrt(2.0) * kSpacing);
    QVERIFY2(std::abs(m.height - 1.5) < 1e-3, "the block top is in front: picked, not the floor under it");
    rows = app.properties.rows();
    QCOMPARE(row(rows, "Height difference (m)"), QString("1.500"));
    QCOMPARE(row(rows, "Distance (m)"), QString::number(m.slope, 'f', 3));
    saveScreenshot(app.view, QString::fromStdString((test::scratchDir("gui_inspection") / "measure.png").string()));
    QVERIFY2(test::countHue(grabView(app.view), 55) > 20, "the yellow measured line is drawn");
    // Off: clicks pick features again, the marks go.
    measure->trigger();
    QVERIFY(!app.measure->active());
    QCOMPARE(test::countHue(grabView(app.view), 55), 0);
  }

  void clippingShowsAndCountsExactlyWhatIsInside() {
    std::unique_ptr<MainWindow> window;
    showFloor(window);
    if (QTest::currentTestFailed()) return;
    AppContext& app = window->context();
    auto* dock = window->findChild<QDockWidget*>("clipDock");
    QVERIFY(dock);
    dock->show();
    auto* clip = dock->findChild<ClipPanel*>("clipPanel");
    QVERIFY(clip);
    frameScene(app.scene, app.view, StandardView::Top);
    QVERIFY(test::countHue(grabView(app.view), 0) > 1000);  // the red floor
    // A plan slice 0.2 m thick at the block top's height: only the block is drawn and counted.
    auto* mode = clip->findChild<QComboBox*>("clipMode");
    mode->setCurrentIndex(static_cast<int>(ClipPanel::Mode::PlanSlice));
    QVERIFY(lookingAlong(app, 2));  // the slice seen from the top
    clip->setAxis(2, grid.z() + 1.5, 0.2);
    QCOMPARE(clip->pointsInside(), std::size_t{121});
    QCOMPARE(clip->findChild<QLabel*>("clipCount")->text(), QString("121 points inside"));
    const QImage slice = grabView(app.view);
    saveScreenshot(app.view, QString::fromStdString((test::scratchDir("gui_inspection") / "plan_slice.png").string()));
    QCOMPARE(test::countHue(slice, 0), 0);   // no floor point drawn
    QVERIFY(test::countHue(slice, 120) > 50);  // the block top is
    // A section across X through the block: one row of the floor on each side plus the block.
    mode->setCurrentIndex(static_cast<int>(ClipPanel::Mode::SectionX));
    QVERIFY(lookingAlong(app, 0));  // the section seen along its normal
    clip->setAxis(0, grid.x() + 8.5, kSpacing / 2);  // exactly the column x = 8.5
    QCOMPARE(clip->pointsInside(), std::size_t{101});
    // A box around the block's top.
    mode->setCurrentIndex(static_cast<int>(ClipPanel::Mode::Box));
    clip->setAxis(0, grid.x() + 8.5, 0.45);  // columns 8.3 .. 8.7
    clip->setAxis(1, grid.y() + 8.5, 0.25);  // rows 8.4 .. 8.6
    clip->setAxis(2, grid.z() + 1.5, 0.1);
    QCOMPARE(clip->pointsInside(), std::size_t{5 * 3});
    // Layers added while clipping are clipped too; Off draws everything again.
    mode->setCurrentIndex(static_cast<int>(ClipPanel::Mode::PlanSlice));
    clip->setAxis(2, grid.z() + 1.5, 0.2);
    app.scene.addDataset(floorAndBlock(grid + Eigen::Vector3d(0.05, 0.05, 0.0)));
    QCOMPARE(test::countHue(grabView(app.view), 0), 0);
    mode->setCurrentIndex(static_cast<int>(ClipPanel::Mode::Off));
    QVERIFY(!app.scene.clipBox());
    QVERIFY(test::countHue(grabView(app.view), 0) > 1000);
  }

  void blinkAlternatesBeforeAndAfterUntilStoppedOrRemoved() {
    std::unique_ptr<MainWindow> window;
    showFloor(window);
    if (QTest::currentTestFailed()) return;
    AppContext& app = window->context();
    auto& layer = static_cast<DatasetLayer&>(*app.scene.layers()[0]);
    layer.setTransform(RigidTransform::fromYaw(0.3, {2.0, 0.0, 0.0}));  // a registration result
    app.layers.setCurrentLayer(&layer);
    QAction* blink = test::menuAction(*window, "View", "Blink before/after");
    QVERIFY(blink && blink->isCheckable());
    blink->trigger();
    QVERIFY(blink->isChecked());
    QTRY_VERIFY_WITH_TIMEOUT(!layer.showsTransform(), 2000);  // before
    QTRY_VERIFY_WITH_TIMEOUT(layer.showsTransform(), 2000);   // after
    QTRY_VERIFY_WITH_TIMEOUT(!layer.showsTransform(), 2000);
    blink->trigger();  // off: shown registered again, and it stays so
    QVERIFY(layer.showsTransform());
    QTest::qWait(3 * BlinkReaction::kPeriodMs);
    QVERIFY(layer.showsTransform());
    // Removing the layer while it blinks stops the blinking (no dangling layer).
    blink->trigger();
    QVERIFY(blink->isChecked());
    app.scene.removeLayer(&layer);
    QTRY_VERIFY_WITH_TIMEOUT(!blink->isChecked(), 2000);
    QCOMPARE(app.log.errorCount(), 0);
  }

  void orthographicProjectionIsAToggle() {
    std::unique_ptr<MainWindow> window;
    test::showMainWindow(window, QSize(900, 700));
    if (QTest::currentTestFailed()) return;
    AppContext& app = window->context();
    app.scene.addDataset(floorAndBlock(Eigen::Vector3d::Zero()));
    frameScene(app.scene, app.view, StandardView::Top);
    QAction* ortho = test::menuAction(*window, "View", "Orthographic projection");
    QVERIFY(ortho);
    QVERIFY(!app.view.renderer()->GetActiveCamera()->GetParallelProjection());
    const int perspective = test::hueSpan(grabView(app.view), 0);
    ortho->trigger();
    QVERIFY(app.view.renderer()->GetActiveCamera()->GetParallelProjection());
    // The floor stays framed (the parallel scale fitted to the data, not to nothing).
    const int span = test::hueSpan(grabView(app.view), 0);
    QVERIFY2(span > perspective / 2 && span < 2 * perspective,
             qPrintable(QString("floor span %1 px, %2 px in perspective").arg(span).arg(perspective)));
    ortho->trigger();
    QVERIFY(!app.view.renderer()->GetActiveCamera()->GetParallelProjection());
  }
};

int main(int argc, char** argv) { return test::runGuiTest<GuiInspectionTest>(argc, argv, "PlumbTestsInspection"); }

#include "test_gui_inspection.moc"
