// Colour by dataset (issue 17): View > Colour by dataset gives every dataset one colour of its
// own, the same as long as it is in the scene, and the legend in the view names the visible
// datasets (or scans, in the Scan mode) with their colours. The rendered view is compared with
// a stored picture (tests/gui/baselines/dataset_colours.png, see gui/image_baseline.hpp for
// the tolerance and PLUMB_UPDATE_BASELINES). Pictures of failed comparisons are kept under
// <build>/test-artifacts/gui_dataset_colours/.
#include <QComboBox>
#include <QTest>

#include <algorithm>
#include <memory>

#include "gui/image_baseline.hpp"
#include "gui/image_checks.hpp"
#include "gui/menu_actions.hpp"
#include "gui/open_window.hpp"
#include "support/test_support.hpp"
#include "ui/layers/color_ramp.hpp"
#include "ui/layers/dataset_layer.hpp"
#include "ui/layers/scene.hpp"
#include "ui/panels/layer_tree_panel.hpp"
#include "ui/panels/properties_panel.hpp"
#include "ui/view/scene_legend.hpp"
#include "ui/view/screenshot.hpp"
#include "ui/view/standard_view.hpp"
#include "ui/view/vtk_view_widget.hpp"

using namespace plumb;
using namespace plumb::ui;

namespace {

constexpr int kTimeoutMs = 30000;
const QSize kViewSize(480, 360);

/// A flat `size` m square of points every 0.1 m at x0 <= x, with a gentle slope in y (so the
/// Elevation mode is not one colour); split into `scans` scans along x. Layer name: `name`.ply.
std::shared_ptr<const Dataset> grid(const std::string& name, double x0, double size, int scans = 1) {
  auto data = std::make_shared<Dataset>();
  const int n = static_cast<int>(size / 0.1) + 1;
  for (int s = 0; s < scans; ++s) {
    PointCloud cloud;
    for (int i = s * n / scans; i < (s + 1) * n / scans; ++i)
      for (int j = 0; j < n; ++j)
        cloud.positions.push_back(Eigen::Vector3f(float(x0 + 0.1 * i), float(0.1 * j), float(0.05 * j)));
    Scan scan;
    scan.name = name + "_" + std::to_string(s + 1);
    scan.cloud = std::move(cloud);
    data->scans.push_back(std::move(scan));
  }
  data->source = name + ".ply";  // names the layer; nothing is read from it
  return data;
}

QColor qcolour(const Rgb8& c) { return QColor(c[0], c[1], c[2]); }

}  // namespace

class GuiDatasetColoursTest : public QObject {
  Q_OBJECT

 private slots:
  void init() {
    test::showMainWindow(window_, QSize(1100, 800));
    if (QTest::currentTestFailed()) return;
    AppContext& app = window_->context();
    app.view.setFixedSize(kViewSize);  // the same picture whatever the docks' widths
    QTRY_COMPARE_WITH_TIMEOUT(app.view.size(), kViewSize, 5000);
    // Three stations side by side, the middle one with two scans.
    layers_ = {&app.scene.addDataset(grid("station_a", 0.0, 6.0)),
               &app.scene.addDataset(grid("station_b", 7.0, 6.0, 2)),
               &app.scene.addDataset(grid("station_c", 14.0, 6.0))};
    legend_ = window_->findChild<SceneLegend*>();
    QVERIFY(legend_);
  }
  void cleanup() {
    if (window_) QTRY_VERIFY_WITH_TIMEOUT(window_->context().tasks.runningCount() == 0, kTimeoutMs);
    window_.reset();
  }

  // Each dataset is drawn in its own colour, all its scans alike, and the legend in the view
  // names each one with that colour (as does the Properties legend of the selected one).
  void eachDatasetHasItsOwnColourAndALegendEntry() {
    AppContext& app = window_->context();
    QVERIFY(legend_->entries().empty() && !legend_->visible());
    colourByDataset();
    QImage image = topView();
    std::vector<Rgb8> colours;
    std::vector<int> pixels;
    for (DatasetLayer* d : layers_) {
      QCOMPARE(d->style().mode, PointColorMode::Dataset);
      colours.push_back(d->datasetColour());
      pixels.push_back(test::countColor(image, qcolour(d->datasetColour())));
      QVERIFY2(pixels.back() > 2000, qPrintable(QString("%1: %2 pixels").arg(d->name()).arg(pixels.back())));
    }
    QVERIFY(colours[0] != colours[1] && colours[1] != colours[2] && colours[0] != colours[2]);
    // The two scans of station_b share its colour: its grid is as large in it as the others.
    QVERIFY2(pixels[1] > 0.8 * pixels[0], qPrintable(QString("%1 vs %2").arg(pixels[1]).arg(pixels[0])));

    QVERIFY(legend_->visible());
    QCOMPARE(legend_->entries().size(), std::size_t{3});
    for (std::size_t i = 0; i < 3; ++i) {
      QCOMPARE(legend_->entries()[i].label, layers_[i]->name());
      QCOMPARE(legend_->entries()[i].colour, colours[i]);
    }
    app.layers.setCurrentLayer(layers_[1]);
    const auto rows = app.properties.rows();
    const QString hex = qcolour(colours[1]).name();
    QVERIFY2(std::any_of(rows.begin(), rows.end(),
                         [&](const PropertyRow& r) { return r.first == "station_b.ply" && r.second == hex; }),
             qPrintable(hex));
  }

  // A dataset keeps its colour when others are added or removed; the legend lists the visible
  // datasets only, and the scans of those drawn in the Scan mode.
  void coloursStayWithTheirDatasetsAndTheLegendFollowsTheScene() {
    AppContext& app = window_->context();
    colourByDataset();
    const Rgb8 b = layers_[1]->datasetColour(), c = layers_[2]->datasetColour();
    app.scene.removeLayer(layers_[0]);
    layers_.erase(layers_.begin());
    auto* d = &app.scene.addDataset(grid("station_d", 21.0, 6.0));
    layers_.push_back(d);
    QCOMPARE(layers_[0]->datasetColour(), b);
    QCOMPARE(layers_[1]->datasetColour(), c);
    QVERIFY(d->datasetColour() != b && d->datasetColour() != c);
    QCOMPARE(legend_->entries().size(), std::size_t{2});  // station_d is not coloured by dataset yet

    // Its own colour chosen in Properties > Colour by: in the legend too.
    app.layers.setCurrentLayer(d);
    auto* mode = app.properties.findChild<QComboBox*>("colorMode");
    QVERIFY(mode);
    mode->setCurrentIndex(static_cast<int>(PointColorMode::Dataset));
    QTRY_VERIFY_WITH_TIMEOUT(!d->coloringPending(), kTimeoutMs);
    QCOMPARE(legend_->entries().size(), std::size_t{3});
    QCOMPARE(legend_->entries().back().colour, d->datasetColour());
    QVERIFY(test::countColor(topView(), qcolour(d->datasetColour())) > 2000);

    // Hidden: out of the legend. Scan mode: one entry per scan, in the scans' colours.
    layers_[1]->setVisible(false);
    app.scene.layerChanged(layers_[1]);
    QCOMPARE(legend_->entries().size(), std::size_t{2});
    app.scene.requestStyle(*layers_[0], PointStyle{PointColorMode::Scan, {}, 2.0});
    QTRY_VERIFY_WITH_TIMEOUT(!layers_[0]->coloringPending(), kTimeoutMs);
    const auto& entries = legend_->entries();
    QCOMPARE(entries.size(), std::size_t{3});
    QCOMPARE(entries[0].label, QString("station_b.ply: station_b_1"));
    QCOMPARE(entries[1].label, QString("station_b.ply: station_b_2"));
    QVERIFY(entries[0].colour != entries[1].colour);

    // No dataset in either mode: the legend goes.
    for (DatasetLayer* layer : {layers_[0], d}) app.scene.removeLayer(layer);
    QVERIFY(legend_->entries().empty() && !legend_->visible());
  }

  // The colour-by-dataset view as stored: three stations, their colours and the legend.
  // A view in other colours (Elevation) must not pass for it.
  void theDatasetViewMatchesItsBaseline() {
    colourByDataset();
    const auto artefacts = test::scratchDir("gui_dataset_colours");
    const QImage image = topView();
    QCOMPARE(image.size(), kViewSize);
    const test::BaselineCheck check = test::checkBaseline(image, "dataset_colours", artefacts);
    QVERIFY2(check.ok, qPrintable(check.message));

    for (DatasetLayer* d : layers_) window_->context().scene.requestStyle(*d, PointStyle{PointColorMode::Elevation, {}, 2.0});
    QTRY_VERIFY_WITH_TIMEOUT(std::none_of(layers_.begin(), layers_.end(), [](auto* d) { return d->coloringPending(); }),
                             kTimeoutMs);
    const test::ImageDifference other =
        test::compareImages(topView(), QImage(QString::fromStdString(test::baselinePath("dataset_colours").string())));
    QVERIFY(other.problem.isEmpty());
    QVERIFY2(other.differing > 0.05, qPrintable(QString::number(other.differing)));
  }

 private:
  /// View > Colour by dataset, then waits for the colours.
  void colourByDataset() {
    QAction* action = test::menuAction(*window_, "View", "Colour by dataset");
    QVERIFY(action);
    action->trigger();
    QTRY_VERIFY_WITH_TIMEOUT(std::none_of(layers_.begin(), layers_.end(), [](auto* d) { return d->coloringPending(); }),
                             kTimeoutMs);
  }
  /// The whole scene from the top, rendered now.
  QImage topView() {
    AppContext& app = window_->context();
    double bounds[6];
    app.scene.renderBounds(app.scene.visibleBounds(), bounds);
    applyStandardView(app.view.renderer(), StandardView::Top, bounds);
    return grabView(app.view);
  }

  std::unique_ptr<MainWindow> window_;
  std::vector<DatasetLayer*> layers_;
  SceneLegend* legend_ = nullptr;
};

int main(int argc, char** argv) { return test::runGuiTest<GuiDatasetColoursTest>(argc, argv); }

#include "test_gui_dataset_colours.moc"
