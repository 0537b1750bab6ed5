// Manual alignment as surveyors use it (issue 17): labelled markers for every pick, a pair left
// out of the fit stays as a check point with its residual, the fit and RMS update live, and the
// levelled fit turns about the vertical only.
#include <QCheckBox>
#include <QLabel>
#include <QTableWidget>
#include <QTest>

#include "gui/image_checks.hpp"
#include "gui/open_window.hpp"
#include "support/test_support.hpp"
#include "ui/layers/dataset_layer.hpp"
#include "ui/layers/layer_transform.hpp"
#include "ui/layers/scene.hpp"
#include "ui/main_window.hpp"
#include "ui/registration/manual_align_panel.hpp"
#include "ui/registration/registration_panel.hpp"
#include "ui/view/screenshot.hpp"
#include "ui/view/standard_view.hpp"
#include "ui/view/vtk_view_widget.hpp"

using namespace plumb;
using namespace plumb::ui;

class GuiManualAlignTest : public QObject {
  Q_OBJECT

 private slots:
  void pairsAreLabelledCheckedLiveAndLevelled() {
    std::unique_ptr<MainWindow> window;
    test::showMainWindow(window, QSize(1200, 800));
    if (QTest::currentTestFailed()) return;
    AppContext& app = window->context();
    // A levelled station turned by 25 deg and shifted: four picks, the third one wrong by 0.5 m.
    const RigidTransform truth = RigidTransform::fromYaw(25.0 * M_PI / 180.0, {3.0, -2.0, 0.4});
    const std::vector<Eigen::Vector3d> picks{{0, 0, 0}, {6, 0, 0.5}, {0, 4, 2.5}, {5, 3, 1.0}};
    PointCloud source_cloud, target_cloud;
    for (int i = 0; i <= 60; ++i)
      for (int j = 0; j <= 40; ++j) {
        const Eigen::Vector3d p(0.1 * i, 0.1 * j, 0.0);
        source_cloud.positions.push_back(p.cast<float>());
        target_cloud.positions.push_back(truth.apply(p).cast<float>());
      }
    auto& source = app.scene.addDataset(std::make_shared<const Dataset>(Dataset::fromCloud(std::move(source_cloud))));
    auto& target = app.scene.addDataset(std::make_shared<const Dataset>(Dataset::fromCloud(std::move(target_cloud))));
    app.registration->setSourceLayer(&source);
    app.registration->setTargetLayer(&target);
    ManualAlignPanel& manual = *app.manual;
    for (std::size_t i = 0; i < picks.size(); ++i)
      manual.addPair(picks[i], truth.apply(picks[i]) + (i == 2 ? Eigen::Vector3d(0.5, 0, 0) : Eigen::Vector3d::Zero()));

    // Every pick is a labelled marker in the view.
    QCOMPARE(manual.markerLabels(), (QStringList{"S1", "T1", "S2", "T2", "S3", "T3", "S4", "T4"}));
    applyStandardView(app.view.renderer(), StandardView::Top);
    const QImage view = grabView(app.view);
    saveScreenshot(app.view, QString::fromStdString((test::scratchDir("gui_manual_align") / "markers.png").string()));
    QVERIFY2(test::countHue(view, 33) > 20, "orange source markers drawn");
    QVERIFY2(test::countHue(view, 191) > 20, "cyan target markers drawn");

    // The fit is live: with the wrong pick in, the RMS shows it.
    auto* status = manual.findChild<QLabel*>("manualStatus");
    QVERIFY(manual.fit());
    QVERIFY(manual.fit()->rms > 0.1);
    // Untick it (as a user does, in the table): it becomes a check point with its residual.
    auto* table = manual.findChild<QTableWidget*>("pairsTable");
    table->item(2, 1)->setCheckState(Qt::Unchecked);
    QVERIFY(!manual.pairUsed(2));
    QVERIFY(manual.fit()->rms < 1e-5);
    QVERIFY(std::abs(manual.residual(2) - 0.5) < 0.01);
    QVERIFY2(status->text().contains("1 check pair(s): RMS 0.5"), qPrintable(status->text()));
    QCOMPARE(table->item(2, 4)->text(), QString("0.5000"));

    // Levelled: two used pairs are enough, and the fit has no tilt.
    manual.setPairUsed(3, false);
    QVERIFY(!manual.fit());
    QVERIFY2(status->text().contains("at least 3"), qPrintable(status->text()));
    manual.findChild<QCheckBox*>("levelledPairs")->setChecked(true);
    QVERIFY(manual.fit());
    QVERIFY(manual.fit()->used == 2 && manual.fit()->rms < 1e-5);
    QVERIFY2(std::abs(manual.residual(3)) < 1e-5, "the right check pair agrees with the levelled fit");
    QVERIFY(std::abs(manual.residual(2) - 0.5) < 0.01);

    // Align applies it; the source markers follow the source onto the target ones.
    QVERIFY(manual.align());
    const RigidTransform found = layerTransform(source);
    QVERIFY(RigidTransform::rotationErrorDeg(found, truth) < 1e-4);
    QVERIFY(RigidTransform::translationError(found, truth) < 1e-4);
    QCOMPARE(manual.markerLabels().size(), 8);
  }
};

int main(int argc, char** argv) { return test::runGuiTest<GuiManualAlignTest>(argc, argv, "PlumbTestsManual"); }

#include "test_gui_manual_align.moc"
