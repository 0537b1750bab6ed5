// The memory budget in the desktop (issue 16, "Memory is a parameter"): the status bar shows
// the memory Plumb holds against the budget; a point file whose display would exceed the budget
// opens as a voxel subsample, said in the log and the Properties; exporting that layer streams
// the whole file through the registration transform, every point kept to 0.1 mm at national-grid
// coordinates. The file's level-of-detail cache is built in the background and its nodes drawn
// over the subsample where the view needs them, coloured like the dataset; a second opening
// reuses the cache.
#include <QLabel>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <fstream>

#include "gui/open_window.hpp"
#include "io/io.hpp"
#include "support/test_support.hpp"
#include "ui/layers/dataset_layer.hpp"
#include "ui/layers/scan_layer.hpp"
#include "ui/layers/color_ramp.hpp"
#include "ui/layers/scene.hpp"
#include "ui/lod/detail_layer.hpp"
#include "ui/panels/memory_status_widget.hpp"
#include "ui/registration/registration_panel.hpp"
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

/// A binary PLY with double coordinates: a 1 cm grid in Lambert-93 coordinates.
std::filesystem::path writeGeoGrid(const std::filesystem::path& path) {
  std::ofstream out(path, std::ios::binary);
  out << "ply\nformat binary_little_endian 1.0\nelement vertex " << kColumns * kRows
      << "\nproperty double x\nproperty double y\nproperty double z\nend_header\n";
  for (int i = 0; i < kColumns; ++i)
    for (int j = 0; j < kRows; ++j) {
      const Eigen::Vector3d p = gridPoint(i, j);
      out.write(reinterpret_cast<const char*>(p.data()), 3 * sizeof(double));
    }
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
    PointStyle scan_style = layer.style();
    scan_style.mode = PointColorMode::Scan;
    app.scene.requestStyle(layer, scan_style);
    QTRY_VERIFY_WITH_TIMEOUT((app.view.requestRender(), detail->drawn().colouring.coloring.style.mode == PointColorMode::Scan),
                             60000);
    const Rgb expected = categoryColor(layer.scans().front()->colourIndex());
    const auto& colours = detail->drawn().colours;
    QVERIFY(!colours.empty());
    QVERIFY(std::all_of(colours.begin(), colours.end(), [&](const Rgba& c) {
      return c[0] == expected[0] && c[1] == expected[1] && c[2] == expected[2];
    }));
  }

  std::unique_ptr<MainWindow> window_;
  std::filesystem::path cache_dir_;
};

int main(int argc, char** argv) { return test::runGuiTest<GuiMemoryBudgetTest>(argc, argv); }
#include "test_gui_memory_budget.moc"
