// GUI test of File > Attach trajectory: a mobile scan from another tool (LAS: GPS times, no
// sensor origins) gets its origins from the vehicle trajectory file, as plumb-cli register
// --target-trajectory does, and the indoor scans then register onto it through the
// Registration dock. Data: the demo survey of the "house" preset (core/simulation), the MMS
// pass written as LAS (which has no field for sensor origins) and its trajectory as
// "t x y z" lines in the outdoor dataset frame (like plumb-cli simulate's trajectory.txt).
#include <QApplication>
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>

#include <algorithm>
#include <fstream>
#include <limits>

#include "gui/menu_actions.hpp"
#include "io/io.hpp"
#include "simulation/building_generator.hpp"
#include "simulation/presets.hpp"
#include "simulation/survey.hpp"
#include "gui/open_window.hpp"
#include "support/test_support.hpp"
#include "ui/actions/file_dialogs.hpp"
#include "ui/layers/dataset_layer.hpp"
#include "ui/layers/layer_transform.hpp"
#include "ui/layers/scene.hpp"
#include "ui/main_window.hpp"
#include "ui/panels/layer_tree_panel.hpp"
#include "ui/panels/log_panel.hpp"
#include "ui/project/project_file.hpp"
#include "ui/registration/quality_report_view.hpp"
#include "ui/registration/registration_panel.hpp"
#include "ui/tasks/task_manager.hpp"
#include "ui/view/surface_format.hpp"

using namespace plumb;
using namespace plumb::ui;
using plumb::test::menuAction;

namespace {

constexpr int kTaskTimeoutMs = 180000;

QString q(const std::filesystem::path& p) { return QString::fromStdString(p.string()); }

struct Demo {
  std::filesystem::path dir, indoor, outdoor_las, trajectory, bad_trajectory;
  RigidTransform indoor_to_outdoor;  ///< the truth the registration must find
  Dataset outdoor;                   ///< the simulated MMS dataset, with its true origins
};

const Demo& demo() {
  static const Demo d = [] {
    Demo out;
    out.dir = test::scratchDir("gui_trajectory_data");
    const GeneratedBuilding b = generateBuilding(buildingPreset("house"));
    const SimulatedSurvey s = simulateSurvey(b.model, b.glass_triangles, b.truth.footprint,
                                             demoSurveyRequest(b.spec, 7));
    const SimulatedDataset* indoor = nullptr;
    const SimulatedDataset* outdoor = nullptr;
    for (const auto& ds : s.datasets) (ds.name == "indoor" ? indoor : outdoor) = &ds;
    if (!indoor || !outdoor || !s.mms_trajectory) throw std::runtime_error("demo survey incomplete");
    out.indoor = out.dir / "indoor.e57";
    out.outdoor_las = out.dir / "outdoor.las";
    writeDataset(out.indoor, indoor->data);
    writeDataset(out.outdoor_las, outdoor->data);
    out.indoor_to_outdoor = outdoor->truth.inverse() * indoor->truth;
    out.outdoor = outdoor->data;
    // The trajectory in the outdoor dataset frame, as plumb-cli simulate writes it.
    out.trajectory = out.dir / "trajectory.txt";
    std::ofstream t(out.trajectory);
    t.precision(std::numeric_limits<double>::max_digits10);
    t << "# t x y z\n";
    const RigidTransform model_to_outdoor = outdoor->truth.inverse();
    for (std::size_t i = 0; i < s.mms_trajectory->times.size(); ++i) {
      const Eigen::Vector3d p = model_to_outdoor.apply(s.mms_trajectory->positions[i]);
      t << s.mms_trajectory->times[i] << " " << p.x() << " " << p.y() << " " << p.z() << "\n";
    }
    // A trajectory on another time base (GPS week seconds vs. seconds of day): refused.
    out.bad_trajectory = out.dir / "shifted.txt";
    std::ofstream bad(out.bad_trajectory);
    for (int i = 0; i < 10; ++i) bad << 400000 + i << " 0 0 0\n";
    return out;
  }();
  return d;
}

/// World position (dataset frame) of every sensor origin of a dataset.
std::vector<Eigen::Vector3d> worldOrigins(const Dataset& d) {
  std::vector<Eigen::Vector3d> out;
  for (const auto& scan : d.scans)
    for (const auto& o : scan.cloud.sensor_origins)
      out.push_back(scan.pose.apply(scan.cloud.offset + o.cast<double>()));
  return out;
}

}  // namespace

class GuiTrajectoryTest : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase() { demo(); }

  void init() {
    test::openWindowWithFiles(window_, {q(demo().indoor), q(demo().outdoor_las)});
    if (QTest::currentTestFailed()) return;
    AppContext& app = window_->context();
    indoor_ = findLayerBySource(app.scene, q(demo().indoor));
    outdoor_ = static_cast<DatasetLayer*>(findLayerBySource(app.scene, q(demo().outdoor_las)));
    QVERIFY(indoor_ && outdoor_);
    QVERIFY(!outdoor_->dataset().scans.at(0).cloud.hasSensorOrigins());  // LAS has none
    QVERIFY(outdoor_->dataset().scans.at(0).cloud.hasTimestamps());
  }
  void cleanup() {
    setFileChooser({});
    window_.reset();
  }

  void attachedTrajectoryGivesOriginsAndTheRegistrationSucceeds() {
    AppContext& app = window_->context();
    attach(demo().trajectory);
    QVERIFY2(app.log.errorCount() == 0, qPrintable(app.log.toPlainText()));
    QCOMPARE(outdoor_->trajectoryPath(), q(demo().trajectory));
    bool row = false;
    for (const auto& r : outdoor_->describe()) row = row || (r.first == "Trajectory" && r.second == q(demo().trajectory));
    QVERIFY(row);

    // The origins interpolated at each point's time are where the simulated sensor was (the
    // trajectory is the polyline the simulator drove, so a wrong time mapping shows as metres).
    const std::vector<Eigen::Vector3d> got = worldOrigins(outdoor_->dataset());
    const std::vector<Eigen::Vector3d> truth = worldOrigins(demo().outdoor);
    QCOMPARE(got.size(), truth.size());
    std::vector<double> err(got.size());
    for (std::size_t i = 0; i < got.size(); ++i) err[i] = (got[i] - truth[i]).norm();
    std::sort(err.begin(), err.end());
    const double median = err[err.size() / 2], p99 = err[err.size() * 99 / 100];
    qInfo("sensor origins from the trajectory vs simulated: median %.4f m, 99%% %.4f m, max %.4f m", median,
          p99, err.back());
    QVERIFY2(p99 < 0.05, qPrintable(QString::number(p99)));

    // Register the indoor scans onto the LAS through the dock: the openings method needs the
    // origins (without them the CLI fails, test_cli_trajectory).
    RegistrationPanel& panel = *app.registration;
    panel.setSourceLayer(indoor_);
    panel.setTargetLayer(outdoor_);
    QSignalSpy finished(&panel, &RegistrationPanel::registrationFinished);
    QTest::mouseClick(panel.findChild<QPushButton*>("register"), Qt::LeftButton);
    QVERIFY(finished.wait(kTaskTimeoutMs));
    QVERIFY2(finished.at(0).at(0).toBool(), qPrintable(panel.report().verdict()));
    const RigidTransform T = layerTransform(*indoor_);
    const double rot = RigidTransform::rotationErrorDeg(T, demo().indoor_to_outdoor);
    const double shift = RigidTransform::translationError(T, demo().indoor_to_outdoor);
    qInfo("indoor onto the LAS with its trajectory: rotation error %.4f deg, translation error %.4f m", rot, shift);
    QVERIFY2(rot < 0.1 && shift < 0.03, qPrintable(QString("%1 deg, %2 m").arg(rot).arg(shift)));

    // The project keeps the trajectory and attaches it again when opened.
    const QString project = q(demo().dir / "with_trajectory.plumb.json");
    saveProject(app, project);
    bool opened = false, all_ok = false;
    openProject(app, project, [&](bool ok, const std::vector<Layer*>&) { opened = true, all_ok = ok; });
    QTRY_VERIFY_WITH_TIMEOUT(opened, 60000);
    QVERIFY2(all_ok, qPrintable(app.log.toPlainText()));
    auto* reopened = static_cast<DatasetLayer*>(findLayerBySource(app.scene, q(demo().outdoor_las)));
    QVERIFY(reopened);
    QCOMPARE(reopened->trajectoryPath(), q(demo().trajectory));
    QVERIFY(reopened->dataset().scans.at(0).cloud.hasSensorOrigins());
  }

  void aTrajectoryOnAnotherTimeBaseIsRefusedWithTheFileNamed() {
    AppContext& app = window_->context();
    attach(demo().bad_trajectory);
    QCOMPARE(app.log.errorCount(), 1);
    const QString log = app.log.toPlainText();
    QVERIFY2(log.contains(q(demo().bad_trajectory)), qPrintable(log));
    QVERIFY(outdoor_->trajectoryPath().isEmpty());
    QVERIFY(!outdoor_->dataset().scans.at(0).cloud.hasSensorOrigins());
    // Cancelling the file dialog does nothing.
    attach({});
    QCOMPARE(app.log.errorCount(), 1);
  }

 private:
  /// File > Attach trajectory on the outdoor layer, the dialog answered with `file` (empty:
  /// cancelled); waits for the background task.
  void attach(const std::filesystem::path& file) {
    AppContext& app = window_->context();
    app.layers.setCurrentLayer(outdoor_);
    QStringList asked;
    setFileChooser([&](FileRequest request, const QString& caption, const QString&, const QString&) {
      asked << caption;
      return request == FileRequest::OpenFile && !file.empty() ? QStringList{q(file)} : QStringList{};
    });
    QAction* action = menuAction(*window_, "File", "Attach trajectory...");
    QVERIFY(action);
    QSignalSpy idle(&app.tasks, &TaskManager::idle);
    action->trigger();
    QCOMPARE(asked.size(), 1);
    QVERIFY(asked.front().contains(outdoor_->name()));
    if (!file.empty()) QVERIFY(idle.wait(60000));
  }

  std::unique_ptr<MainWindow> window_;
  Layer* indoor_ = nullptr;
  DatasetLayer* outdoor_ = nullptr;
};

int main(int argc, char** argv) {
  setDefaultSurfaceFormat();
  QApplication app(argc, argv);
  GuiTrajectoryTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "test_gui_trajectory.moc"
