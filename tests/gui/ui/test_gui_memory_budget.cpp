// The memory budget in the desktop (issue 16, "Memory is a parameter"): the status bar shows
// the memory Plumb holds against the budget; a point file whose display would exceed the budget
// opens as a voxel subsample, said in the log and the Properties; exporting that layer streams
// the whole file through the registration transform, every point kept to 0.1 mm at national-grid
// coordinates. The file's level-of-detail cache is built in the background and its nodes drawn
// over the subsample where the view needs them, coloured like the dataset; a second opening
// reuses the cache. Files opened together share the budget and the still frame's detail.
#include <QLabel>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <span>
#include <fstream>

#include "gui/open_window.hpp"
#include "io/io.hpp"
#include "support/test_support.hpp"
#include "ui/layers/dataset_layer.hpp"
#include "ui/layers/scan_layer.hpp"
#include "ui/layers/color_ramp.hpp"
#include "ui/layers/scene.hpp"
#include "ui/lod/detail_layer.hpp"
#include "ui/lod/detail_points.hpp"
#include "ui/panels/memory_status_widget.hpp"
#include "ui/registration/point_picking.hpp"
#include "ui/registration/registration_panel.hpp"
#include "ui/registration/registration_runner.hpp"
#include "ui/tasks/export_tasks.hpp"
#include "ui/tasks/load_budget.hpp"
#include "ui/tasks/task.hpp"
#include "ui/view/vtk_view_widget.hpp"

using namespace plumb;
using namespace plumb::ui;

namespace {
QString q(const std::filesystem::path& p) { return QString::fromStdString(p.string()); }

constexpr int kColumns = 1100, kRows = 1000;  // 1.1 million points: 330 MB at 300 B a point
constexpr double kX0 = 651000.1234, kY0 = 6860000.5678, kStep = 0.01;

Eigen::Vector3d gridPoint(int i, int j) {
  return {kX0 + i * kStep, kY0 + j * kStep, 40.0 + 0.001 * ((i * 7 + j * 3) % 11)};
}

/// Intensity in [0, 0.99], but 1000 at every 10007th point (retro-reflective targets).
float gridIntensity(int i, int j) {
  const int k = i * kRows + j;
  return k % 10007 == 0 ? 1000.0f : float((i * 13 + j * 7) % 100) / 100.0f;
}

/// A binary PLY with double coordinates: a 1 cm grid in Lambert-93 coordinates, with intensity.
std::filesystem::path writeGeoGrid(const std::filesystem::path& path) {
  std::ofstream out(path, std::ios::binary);
  out << "ply\nformat binary_little_endian 1.0\nelement vertex " << kColumns * kRows
      << "\nproperty double x\nproperty double y\nproperty double z\nproperty float intensity\nend_header\n";
  for (int i = 0; i < kColumns; ++i)
    for (int j = 0; j < kRows; ++j) {
      const Eigen::Vector3d p = gridPoint(i, j);
      out.write(reinterpret_cast<const char*>(p.data()), 3 * sizeof(double));
      const float v = gridIntensity(i, j);
      out.write(reinterpret_cast<const char*>(&v), sizeof v);
    }
  return path;
}

/// A horizontal square at height z, 2 triangles, wider than the grid (OBJ, facing up).
std::filesystem::path writePlane(const std::filesystem::path& path, double z) {
  std::ofstream out(path);
  out.precision(12);
  const double x0 = kX0 - 1, x1 = kX0 + kColumns * kStep + 1, y0 = kY0 - 1, y1 = kY0 + kRows * kStep + 1;
  out << "v " << x0 << " " << y0 << " " << z << "\nv " << x1 << " " << y0 << " " << z << "\nv " << x1 << " " << y1
      << " " << z << "\nv " << x0 << " " << y1 << " " << z << "\nf 1 2 3\nf 1 3 4\n";
  return path;
}

bool waitFor(Task* task) {
  QSignalSpy done(task, &Task::finished);
  if (!done.wait(120000)) return false;
  if (!done.first().at(0).toBool()) qWarning("task failed: %s", qPrintable(done.first().at(1).toString()));
  return done.first().at(0).toBool();
}
}  // namespace

class GuiMemoryBudgetTest : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase() {
    cache_dir_ = test::scratchDir("gui_memory_budget_cache");
    qputenv("PLUMB_LOD_CACHE_DIR", QByteArray::fromStdString(cache_dir_.string()));
  }
  void init() {
    test::showMainWindow(window_, QSize(1200, 800));
  }
  void cleanup() { window_.reset(); }

  void statusBarShowsMemoryAgainstTheBudget() {
    AppContext& app = window_->context();
    auto* status = window_->statusBar()->findChild<MemoryStatusWidget*>("memoryStatus");
    QVERIFY(status);
    app.registration->params().memory.budget_mb = 3072;
    status->refresh();
    QVERIFY2(status->text().startsWith("Memory ") && status->text().endsWith("/ 3.0 GB"),
             qPrintable(status->text()));
    QCOMPARE(MemoryStatusWidget::format(std::uint64_t{1} << 30, std::uint64_t{3} << 30),
             QString("Memory 1.0 / 3.0 GB"));
    // A budget below what the window holds: the figure turns red.
    app.registration->params().memory.budget_mb = 1;
    status->refresh();
    QVERIFY2(status->styleSheet().contains("#c62828"), qPrintable(status->styleSheet()));
  }

  void aFileAboveTheBudgetOpensAsASubsampleAndExportsWhole() {
    AppContext& app = window_->context();
    const auto dir = test::scratchDir("gui_memory_budget");
    const auto file = writeGeoGrid(dir / "grid.ply");
    app.registration->params().memory.budget_mb = 256;  // 1.1 M points x 300 B > 256 MB
    QSignalSpy idle(&app.tasks, &TaskManager::idle);
    window_->openFiles({q(file)});
    QVERIFY(idle.wait(120000));
    QCOMPARE(app.log.errorCount(), 0);
    QCOMPARE(app.scene.layers().size(), std::size_t{1});
    auto* layer = dynamic_cast<DatasetLayer*>(app.scene.layers()[0].get());
    QVERIFY(layer);
    QVERIFY(layer->subsampledFrom().has_value());
    QCOMPARE(layer->subsampledFrom()->points_in_file, std::uint64_t(kColumns) * kRows);
    const std::size_t shown = layer->dataset().pointCount();
    const std::size_t most = (std::uint64_t{256} << 20) / kDisplayBytesPerPoint;
    QVERIFY2(shown > 100000 && shown <= most, qPrintable(QString::number(shown)));
    QVERIFY(app.log.toPlainText().contains("voxel subsample"));
    bool row = false;
    for (const auto& r : layer->describe()) row |= r.first == "Subsample";
    QVERIFY(row);
    checkDetail(*layer, shown);

    // A registration transform, then the export: the whole file, each point moved by it.
    const RigidTransform T(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()).toRotationMatrix(),
                           Eigen::Vector3d(12.5, -7.25, 0.375));
    layer->setTransform(T);
    const auto out = dir / "grid_registered.ply";
    QVERIFY(waitFor(exportRegisteredDataset(app, *layer, q(out))));
    const Dataset back = readDataset(out);
    QCOMPARE(back.pointCount(), std::size_t(kColumns) * kRows);
    const PointCloud& cloud = back.scans.at(0).cloud;
    const RigidTransform pose = back.scans.at(0).pose;
    double worst = 0;
    for (std::size_t k = 0; k < cloud.size(); k += 997) {
      const int i = int(k / kRows), j = int(k % kRows);
      const Eigen::Vector3d expected = T.apply(gridPoint(i, j));
      const Eigen::Vector3d got = pose.apply(cloud.world(k));
      worst = std::max(worst, (got - expected).norm());
    }
    QVERIFY2(worst <= 1e-4, qPrintable(QString::number(worst)));
  }

  void aFileWithinTheBudgetOpensWhole() {
    AppContext& app = window_->context();
    const auto file = writeGeoGrid(test::scratchDir("gui_memory_budget_whole") / "grid.ply");
    app.registration->params().memory.budget_mb = 1024;  // 330 MB fits
    QSignalSpy idle(&app.tasks, &TaskManager::idle);
    window_->openFiles({q(file)});
    QVERIFY(idle.wait(120000));
    auto* layer = dynamic_cast<DatasetLayer*>(app.scene.layers().at(0).get());
    QVERIFY(layer);
    QVERIFY(!layer->subsampledFrom().has_value());
    QCOMPARE(layer->dataset().pointCount(), std::size_t(kColumns) * kRows);
  }

  /// A campaign of files opened together shares the one budget: two files that would each
  /// open whole alone (330 MB of 400) are both subsamples, together within the budget; a file
  /// opened afterwards gets what is left. Their details share the still frame's budget.
  void filesOpenedTogetherShareTheBudget() {
    AppContext& app = window_->context();
    const auto dir = test::scratchDir("gui_memory_budget_shared");
    const auto a = writeGeoGrid(dir / "grid_a.ply"), b = writeGeoGrid(dir / "grid_b.ply");
    app.registration->params().memory.budget_mb = 400;
    const std::uint64_t budget = std::uint64_t{400} << 20;
    QSignalSpy idle(&app.tasks, &TaskManager::idle);
    window_->openFiles({q(a), q(b)});
    QVERIFY(idle.wait(120000));
    QCOMPARE(app.log.errorCount(), 0);
    QCOMPARE(app.scene.layers().size(), std::size_t{2});
    for (const auto& l : app.scene.layers()) {
      auto* layer = dynamic_cast<DatasetLayer*>(l.get());
      QVERIFY(layer && layer->subsampledFrom().has_value());
      QVERIFY(layer->dataset().pointCount() <= budget / 2 / kDisplayBytesPerPoint);
    }
    QVERIFY2(app.log.toPlainText().contains("its part of the memory budget (0.20 of 0.39 GB)"),
             qPrintable(app.log.toPlainText()));
    QCOMPARE(app.loads_reserved, std::uint64_t{0});
    const std::uint64_t held = heldBytes(app);
    QVERIFY(held <= budget);
    // The details of both, after still frames: each selected within half the still frame's
    // budget (the frame's budget adapts to the frame time, so each load records its share).
    QTRY_VERIFY_WITH_TIMEOUT((app.view.requestRender(), detailPoints(app) > 0), 60000);
    for (const auto& l : app.scene.layers()) {
      DetailLayer* detail = detailOf(static_cast<DatasetLayer&>(*l));
      QVERIFY(detail);
      // (A detail drawn before the other file's cache was ready had the whole budget.)
      QTRY_VERIFY_WITH_TIMEOUT((app.view.requestRender(), detail->drawnPointCount() > 0 && detail->drawn().layers_sharing == 2),
                               60000);
      QVERIFY2(detail->drawnPointCount() <= detail->drawn().point_budget,
               qPrintable(QString("%1 detail points, budget %2").arg(detail->drawnPointCount()).arg(detail->drawn().point_budget)));
    }
    // A third file now, which would fit the whole budget alone: what the budget leaves.
    const auto c = writeGeoGrid(dir / "grid_c.ply");
    window_->openFiles({q(c)});
    QVERIFY(idle.wait(120000));
    QCOMPARE(app.scene.layers().size(), std::size_t{3});
    auto* third = dynamic_cast<DatasetLayer*>(app.scene.layers()[2].get());
    QVERIFY(third && third->subsampledFrom().has_value());
    QVERIFY(third->dataset().pointCount() * kDisplayBytesPerPoint <= budget - held);
    QVERIFY(heldBytes(app) <= budget);
  }

  /// Colour by distance reaches the detail: each full-resolution point of the file is coloured
  /// by its own distance to the target (a plane 3 cm under the grid, whose points lie 0 to
  /// 1 cm above 40 m), not by elevation as before.
  void theDetailIsColouredByItsOwnDistances() {
    AppContext& app = window_->context();
    const auto dir = test::scratchDir("gui_memory_budget_distances");
    const auto grid = writeGeoGrid(dir / "grid.ply");
    const auto plane = writePlane(dir / "plane.obj", 39.97);
    app.registration->params().memory.budget_mb = 256;
    QSignalSpy idle(&app.tasks, &TaskManager::idle);
    window_->openFiles({q(grid), q(plane)});
    QVERIFY(idle.wait(120000));
    QCOMPARE(app.log.errorCount(), 0);
    auto* layer = dynamic_cast<DatasetLayer*>(app.scene.layers().at(0).get());
    if (!layer) layer = dynamic_cast<DatasetLayer*>(app.scene.layers().at(1).get());
    QVERIFY(layer && layer->subsampledFrom().has_value());
    DetailLayer* detail = nullptr;
    QTRY_VERIFY_WITH_TIMEOUT((detail = detailOf(*layer)) != nullptr, 60000);
    auto* runner = window_->findChild<RegistrationRunner*>();
    QVERIFY(runner);
    QSignalSpy computed(runner, &RegistrationRunner::distancesComputed);
    QVERIFY(runner->computeDistances());
    QVERIFY(computed.wait(120000));
    QVERIFY(computed.first().at(0).toBool());
    QVERIFY(layer->distanceReference());
    const DistanceScale scale{runner->distanceParams().max_distance, runner->distanceParams().signed_distances};
    QTRY_VERIFY_WITH_TIMEOUT((app.view.requestRender(), detail->drawn().colouring.distances != nullptr &&
                              detail->drawnPointCount() > 0),
                             60000);
    const DetailPoints& drawn = detail->drawn();
    std::size_t off = 0;
    for (std::size_t k = 0; k < drawn.positions.size(); k += 101) {
      const float d = float(drawn.anchor.z() + drawn.positions[k].z() - 39.97);
      Rgb want;
      fillDistanceColors(std::span<const float>(&d, 1), scale, std::span<Rgb>(&want, 1));
      const Rgba& got = drawn.colours[k];
      for (int c = 0; c < 3; ++c) off += std::abs(int(got[c]) - int(want[c])) > 3;
    }
    QVERIFY2(off == 0, qPrintable(QString("%1 detail colours are not their point's distance").arg(off)));
  }

  void aSecondOpeningReusesTheCache() {
    AppContext& app = window_->context();
    const auto file = test::scratchDir("gui_memory_budget") / "grid.ply";  // written again: new mtime
    writeGeoGrid(file);
    app.registration->params().memory.budget_mb = 256;
    for (int round = 0; round < 2; ++round) {
      QSignalSpy idle(&app.tasks, &TaskManager::idle);
      window_->openFiles({q(file)});
      QVERIFY(idle.wait(120000));
    }
    const QString log = app.log.toPlainText();
    QCOMPARE(log.count("level-of-detail cache built"), 1);
    QCOMPARE(log.count("level-of-detail cache reused"), 1);
    // The second opening's subsample came from the cache, not from streaming the file, and it
    // stands for the same file: every point counted, within the budget, on the same grid.
    QCOMPARE(log.count("the subsample was made from its level-of-detail cache"), 1);
    QCOMPARE(app.scene.layers().size(), std::size_t{2});
    auto* first = dynamic_cast<DatasetLayer*>(app.scene.layers()[0].get());
    auto* second = dynamic_cast<DatasetLayer*>(app.scene.layers()[1].get());
    QVERIFY(first && second && second->subsampledFrom());
    QCOMPARE(second->subsampledFrom()->points_in_file, std::uint64_t(kColumns) * kRows);
    const std::size_t most = (std::uint64_t{256} << 20) / kDisplayBytesPerPoint;
    QVERIFY(second->dataset().pointCount() <= most);
    QVERIFY2(second->dataset().pointCount() > first->dataset().pointCount() / 4,
             qPrintable(QString("%1 vs %2").arg(second->dataset().pointCount()).arg(first->dataset().pointCount())));
    const Bounds a = first->dataset().bounds(), b = second->dataset().bounds();
    QVERIFY2((a.min - b.min).norm() < 0.1 && (a.max - b.max).norm() < 0.1, "the two subsamples cover the same grid");
  }

 private:
  /// The dataset's DetailLayer: built, then drawn after a still frame with more points than the
  /// subsample; the Scan colour mode colours every detail point with the scan's colour.
  void checkDetail(DatasetLayer& layer, std::size_t subsample) {
    AppContext& app = window_->context();
    DetailLayer* detail = nullptr;
    for (const auto& c : layer.children())
      if (c->kind() == LayerKind::Detail) detail = static_cast<DetailLayer*>(c.get());
    QVERIFY2(detail, qPrintable(app.log.toPlainText()));
    QCOMPARE(detail->cache()->hierarchy().points, std::uint64_t(kColumns) * kRows);
    QVERIFY(app.log.toPlainText().contains("level-of-detail cache built"));
    // Still frames (the first after the load may already have drawn it) until the detail is in.
    QTRY_VERIFY2_WITH_TIMEOUT((app.view.requestRender(), detail->drawnPointCount() > subsample),
                              qPrintable(QString("%1 detail points, %2 in the subsample\n%3")
                                             .arg(detail->drawnPointCount()).arg(subsample).arg(app.log.toPlainText())),
                              60000);
    checkPickingOnDetail(layer, *detail);
    PointStyle scan_style = layer.style();
    scan_style.mode = PointColorMode::Scan;
    scan_style.point_size = 4.0;
    app.scene.requestStyle(layer, scan_style);
    QTRY_VERIFY_WITH_TIMEOUT((app.view.requestRender(), detail->drawn().colouring.coloring.style.mode == PointColorMode::Scan),
                             60000);
    QCOMPARE(detail->pointSize(), 4.0);  // the dataset's point size, also after a style change
    const Rgb expected = categoryColor(layer.scans().front()->colourIndex());
    const auto& colours = detail->drawn().colours;
    QVERIFY(!colours.empty());
    QVERIFY(std::all_of(colours.begin(), colours.end(), [&](const Rgba& c) {
      return c[0] == expected[0] && c[1] == expected[1] && c[2] == expected[2];
    }));
    // Intensity: the detail's ramp spans the subsample's robust range (1 % - 99 %), not up to
    // the few targets at 1000, which would draw every other point black.
    PointStyle intensity_style = layer.style();
    intensity_style.mode = PointColorMode::Intensity;
    app.scene.requestStyle(layer, intensity_style);
    QTRY_VERIFY_WITH_TIMEOUT((app.view.requestRender(), detail->drawn().colouring.coloring.style.mode == PointColorMode::Intensity),
                             60000);
    const auto& ramp = detail->drawn().colouring.coloring;
    QVERIFY2(ramp.value_max < 1.5 && ramp.value_min < 0.2,
             qPrintable(QString("detail intensity ramp %1 .. %2").arg(ramp.value_min).arg(ramp.value_max)));
  }

  static DetailLayer* detailOf(DatasetLayer& layer) {
    for (const auto& c : layer.children())
      if (c->kind() == LayerKind::Detail) return static_cast<DetailLayer*>(c.get());
    return nullptr;
  }

  static std::size_t detailPoints(AppContext& app) {
    std::size_t n = 0;
    for (const auto& l : app.scene.layers())
      for (const auto& c : l->children())
        if (c->kind() == LayerKind::Detail) n += static_cast<DetailLayer&>(*c).drawnPointCount();
    return n;
  }

  /// Picking sees the detail: with the subsample's scans hidden, a click at the view's centre
  /// picks a point of the file itself (on its 1 cm grid, to 0.1 mm), not a voxel centroid.
  void checkPickingOnDetail(DatasetLayer& layer, DetailLayer& detail) {
    AppContext& app = window_->context();
    for (ScanLayer* s : layer.scans()) s->setVisible(false);
    app.view.renderNow();
    QVERIFY(detail.drawnPointCount() > 0);
    const double dpr = app.view.devicePixelRatioF();
    const auto picked = pickScenePoint(app.view.renderer(), app.scene, int(app.view.width() * dpr / 2),
                                       int(app.view.height() * dpr / 2), 1.0);
    for (ScanLayer* s : layer.scans()) s->setVisible(true);
    QVERIFY2(picked, "nothing picked with only the detail shown");
    const double i = (picked->world.x() - kX0) / kStep, j = (picked->world.y() - kY0) / kStep;
    QVERIFY2(std::abs(i - std::round(i)) < 0.01 && std::abs(j - std::round(j)) < 0.01,
             qPrintable(QString("picked %1, %2: not a point of the file").arg(picked->world.x(), 0, 'f', 5)
                            .arg(picked->world.y(), 0, 'f', 5)));
  }

  std::unique_ptr<MainWindow> window_;
  std::filesystem::path cache_dir_;
};

int main(int argc, char** argv) { return test::runGuiTest<GuiMemoryBudgetTest>(argc, argv); }
#include "test_gui_memory_budget.moc"
