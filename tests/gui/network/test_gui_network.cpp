// The Network dock on a simulated campaign (two furnished rooms, five TLS stations perturbed by
// up to 180 deg and 20 m, as tests/integration/network/test_cli_network.cpp): the run goes off
// the UI thread, places every station within the target of the truth and draws them in
// the plan; a rejected link leaves the adjustment at the re-run, a locked station keeps its pose
// bit for bit, the applied poses move the scans (undoably), the report is written. One campaign
// and one run for the whole suite (the slots run in order and build on each other).
#include <QCheckBox>
#include <QDockWidget>
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>
#include <QTimer>
#include <QUndoStack>

#include <chrono>

#include "gui/menu_actions.hpp"
#include "gui/open_window.hpp"
#include "support/cli_runner.hpp"
#include "support/network_truth.hpp"
#include "support/two_room_campaign.hpp"
#include "ui/actions/file_dialogs.hpp"
#include "ui/layers/dataset_layer.hpp"
#include "ui/layers/scene.hpp"
#include "ui/network/link_status.hpp"
#include "ui/network/link_table.hpp"
#include "ui/network/network_panel.hpp"
#include "ui/network/network_plan_view.hpp"
#include "ui/network/network_runner.hpp"
#include "ui/network/station_table.hpp"
#include "ui/tasks/task.hpp"
#include "ui/tasks/task_manager.hpp"

using namespace plumb;
using namespace plumb::ui;

namespace {
constexpr int kRunTimeoutMs = 300000;
constexpr int kAdjustTimeoutMs = 60000;
constexpr std::size_t kStations = 5;
}  // namespace

class GuiNetworkTest : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase() {
    dir_ = test::scratchDir("gui_network");
    const auto r = test::simulateTwoRoomCampaign(dir_, 5);
    QVERIFY2(r.exit_code == 0, r.err.c_str());
    test::openWindowWithFiles(window_, {QString::fromStdString((dir_ / "sim/indoor.e57").string())});
    QVERIFY(window_);
    QVERIFY(window_->context().network);
  }
  void cleanupTestCase() {
    setFileChooser({});
    if (window_)
      QVERIFY(QTest::qWaitFor([&] { return window_->context().tasks.runningCount() == 0; }, kRunTimeoutMs));
    window_.reset();
  }

  // Before a run there is nothing to re-run; a cancelled run leaves no result and the dock ready.
  void cancelledRunLeavesNoResult() {
    QVERIFY(!panel().findChild<QPushButton*>("networkRerun")->isEnabled());
    QVERIFY(!runner().rerunAdjustment());
    QVERIFY(window_->context().log.toPlainText().contains("register the stations as a network first"));
    QSignalSpy finished(&runner(), &NetworkRunner::finished);
    QVERIFY(panel().run());
    QCOMPARE(window_->context().tasks.runningCount(), 1);
    QTest::qWait(300);
    window_->context().tasks.running().front()->cancel();
    QVERIFY(finished.wait(kRunTimeoutMs));
    QVERIFY(!finished.at(0).at(0).toBool());
    QVERIFY(!runner().session());
    QVERIFY(!runner().busy());
    QVERIFY(window_->context().log.toPlainText().contains("cancelled"));
    QVERIFY(panel().findChild<QPushButton*>("networkRun")->isEnabled());
  }

  // Registration > Register stations as a network... shows the dock; its run goes off the UI
  // thread: the event loop keeps ticking, the run button waits for the task.
  void runsOffTheUiThread() {
    QAction* action = test::menuAction(*window_, "Registration", "Register stations as a network...");
    QVERIFY(action);
    auto* dock = window_->findChild<QDockWidget*>("networkDock");
    QVERIFY(dock && !dock->isVisible());
    action->trigger();
    QVERIFY(dock->isVisible());
    QTest::qWait(1000);  // the view re-renders at its new size first (software GL under Xvfb)

    QTimer timer;
    int ticks = 0;
    auto last = std::chrono::steady_clock::now();
    double longest_gap_s = 0.0;
    connect(&timer, &QTimer::timeout, this, [&] {
      const auto now = std::chrono::steady_clock::now();
      longest_gap_s = std::max(longest_gap_s, std::chrono::duration<double>(now - last).count());
      last = now;
      ++ticks;
    });
    QSignalSpy finished(&runner(), &NetworkRunner::finished);
    auto* run = panel().findChild<QPushButton*>("networkRun");
    QVERIFY(run && run->isEnabled());
    timer.start(20);
    last = std::chrono::steady_clock::now();
    QTest::mouseClick(run, Qt::LeftButton);
    QVERIFY(runner().busy());
    QVERIFY(!run->isEnabled());
    QCOMPARE(window_->context().tasks.runningCount(), 1);
    QVERIFY(!runner().run(nullptr));  // one network task at a time
    QVERIFY(finished.wait(kRunTimeoutMs));
    timer.stop();
    QVERIFY2(finished.at(0).at(0).toBool(), qPrintable(window_->context().log.toPlainText()));
    QVERIFY(run->isEnabled());
    // Seconds of registration: the timer kept firing, never held up for long (0.1 s measured; the
    // margin is for a loaded machine).
    qInfo("%d ticks, longest gap %.3f s", ticks, longest_gap_s);
    QVERIFY2(ticks >= 20, qPrintable(QString::number(ticks)));
    QVERIFY2(longest_gap_s < 0.5, qPrintable(QString::number(longest_gap_s)));
  }

  // Every station placed, drawn in the plan inside the widget, listed in the tables.
  void everyStationIsPlacedAndDrawn() {
    const auto session = runner().session();
    QVERIFY(session);
    QCOMPARE(session->stationCount(), kStations);
    QVERIFY(session->result->complete());
    QCOMPARE(panel().plan().drawnStations().size(), kStations);
    QVERIFY(panel().plan().listedStations().empty());
    for (std::size_t i = 0; i < kStations; ++i) {
      const auto p = panel().plan().stationPoint(i);
      QVERIFY(p && panel().plan().rect().contains(p->toPoint()));
    }
    QCOMPARE(panel().stations().rowCount(), int(kStations));
    QCOMPARE(panel().stations().item(0, StationTable::State)->text(), QString("reference"));
    for (int i = 1; i < int(kStations); ++i)
      QCOMPARE(panel().stations().item(i, StationTable::State)->text(), QString("placed"));
    QCOMPARE(panel().links().rowCount(), int(session->linkCount()));
    const auto shot = dir_ / "network-dock.png";  // to look at when the plan is in doubt
    QVERIFY(panel().grab().save(QString::fromStdString(shot.string())));
  }

  // The adjusted poses against the simulation's truth: the 5 mm / 0.02 deg.
  void posesAreWithinTheTargetOfTruth() {
    const auto session = runner().session();
    std::map<std::string, std::optional<RigidTransform>> poses;
    for (std::size_t i = 0; i < kStations; ++i) poses[(*session->stations)[i].name] = session->result->adjustment.poses[i];
    const auto truth = test::readJsonFile(dir_ / "sim/truth.json");
    const auto errors = test::stationErrors(truth, (*session->stations)[session->result->reference].name, poses);
    QCOMPARE(errors.size(), kStations);
    for (const auto& e : errors) {
      QVERIFY2(e.placed, e.name.c_str());
      QVERIFY2(e.translation_m < 0.005, qPrintable(QString("%1: %2 m").arg(e.name.c_str()).arg(e.translation_m)));
      QVERIFY2(e.rotation_deg < 0.02, qPrintable(QString("%1: %2 deg").arg(e.name.c_str()).arg(e.rotation_deg)));
    }
  }

  // A click on a station or a link in the plan selects its row.
  void planSelectionSelectsInTheTables() {
    NetworkPlanView& plan = panel().plan();
    QTest::mouseClick(&plan, Qt::LeftButton, {}, plan.stationPoint(3)->toPoint());
    QCOMPARE(panel().stations().selectedStation(), 3);
    const int k = keptLoopLink();
    QVERIFY(k >= 0);
    const auto mid = plan.linkPoint(std::size_t(k));
    QVERIFY(mid);
    QTest::mouseClick(&plan, Qt::LeftButton, {}, mid->toPoint());
    QCOMPARE(panel().links().selectedLink(), k);
    QCOMPARE(plan.selectedLink(), k);
  }

  // Reject a kept link (checked by a loop), re-run: it is rejected and out of the adjustment,
  // every station still placed; clearing the decision brings it back.
  void rejectedLinkLeavesTheAdjustment() {
    const int k = keptLoopLink();
    QVERIFY(k >= 0);
    panel().links().selectRow(k);
    clickButton("linkReject");
    QCOMPARE(panel().links().item(k, LinkTable::Decision)->text(), QString("rejected (re-run to apply)"));
    rerun();
    const auto session = runner().session();
    QCOMPARE(linkStatus(session->report["links"][std::size_t(k)]), LinkStatus::Rejected);
    QCOMPARE(panel().links().item(k, LinkTable::Status)->text(), QString("rejected"));
    QCOMPARE(panel().links().item(k, LinkTable::Decision)->text(), QString("rejected"));
    const auto& adjusted = session->result->adjusted;
    QVERIFY(std::find(adjusted.begin(), adjusted.end(), std::size_t(k)) == adjusted.end());
    QVERIFY(session->result->complete());

    panel().links().selectRow(k);
    clickButton("linkClear");
    rerun();
    QVERIFY(inAdjustment(linkStatus(runner().session()->report["links"][std::size_t(k)])));
  }

  // A locked station keeps its pose bit for bit through a re-run that moves the others (a
  // rejected loop link changes the adjustment).
  void lockedStationKeepsItsPose() {
    const std::size_t i = 3;
    const RigidTransform held = *runner().session()->result->adjustment.poses[i];
    const RigidTransform other = *runner().session()->result->adjustment.poses[1];
    panel().stations().item(int(i), StationTable::Lock)->setCheckState(Qt::Checked);
    QVERIFY(runner().isLocked(i));
    panel().links().selectRow(keptLoopLink());
    clickButton("linkReject");
    rerun();
    const auto session = runner().session();
    QVERIFY(session->result->placed(i));
    QVERIFY(session->result->adjustment.poses[i]->matrix() == held.matrix());
    QVERIFY(session->result->adjustment.poses[1]->matrix() != other.matrix());  // the re-run did adjust
    QVERIFY(session->report["stations"][i].value("locked", false));
    QCOMPARE(panel().stations().item(int(i), StationTable::Lock)->checkState(), Qt::Checked);
  }

  // Apply poses gives each scan its adjusted pose in the 3D view; Undo takes it back. Colour by
  // station colours the dataset by scan.
  void applyPosesMovesTheScansUndoably() {
    auto& layer = static_cast<DatasetLayer&>(*window_->context().scene.layers().front());
    const auto before = layer.scanPoses();
    clickButton("networkApply");
    const auto session = runner().session();
    const auto after = layer.scanPoses();
    for (std::size_t i = 0; i < kStations; ++i)
      QVERIFY(after[i].matrix() == session->result->adjustment.poses[i]->matrix());
    QVERIFY(after[1].matrix() != before[1].matrix());
    window_->context().undo.undo();
    for (std::size_t i = 0; i < kStations; ++i) QVERIFY(layer.scanPoses()[i].matrix() == before[i].matrix());
    window_->context().undo.redo();
    QVERIFY(layer.scanPoses()[1].matrix() == after[1].matrix());

    clickButton("networkColour");
    QCOMPARE(layer.style().mode, PointColorMode::Scan);
  }

  // Save report...: JSON and HTML, both as plumb-cli network writes them.
  void reportIsWritten() {
    for (const char* name : {"network.json", "network.html"}) {
      const auto path = dir_ / name;
      setFileChooser([&](FileRequest, const QString&, const QString&, const QString&) {
        return QStringList{QString::fromStdString(path.string())};
      });
      clickButton("networkSaveReport");
      QVERIFY2(std::filesystem::exists(path), name);
    }
    const auto json = test::readJsonFile(dir_ / "network.json");
    QCOMPARE(json["format"].get<std::string>(), std::string("plumb-network-report"));
    QCOMPARE(json["stations"].size(), kStations);
    QVERIFY(json["stations"][3].value("locked", false));
    const std::string html = test::readAll(dir_ / "network.html");
    QVERIFY(html.find("<svg") != std::string::npos);
    for (const auto& s : json["stations"])
      QVERIFY(html.find(">" + s["name"].get<std::string>() + "</text>") != std::string::npos);
  }

 private:
  NetworkPanel& panel() { return *window_->context().network; }
  NetworkRunner& runner() { return panel().runner(); }

  /// The first link kept in the adjustment that a loop checks (not a bridge), -1 if none.
  int keptLoopLink() {
    const auto& links = runner().session()->report["links"];
    for (std::size_t k = 0; k < links.size(); ++k)
      if (linkStatus(links[k]) == LinkStatus::Kept) return int(k);
    return -1;
  }

  void clickButton(const char* name) {
    auto* b = panel().findChild<QPushButton*>(name);
    QVERIFY2(b && b->isEnabled(), name);
    QTest::mouseClick(b, Qt::LeftButton);
  }

  void rerun() {
    QSignalSpy adjusted(&runner(), &NetworkRunner::adjusted);
    clickButton("networkRerun");
    QVERIFY(adjusted.count() == 1 || adjusted.wait(kAdjustTimeoutMs));
    QVERIFY2(adjusted.at(0).at(0).toBool(), qPrintable(window_->context().log.toPlainText()));
  }

  std::filesystem::path dir_;
  std::unique_ptr<MainWindow> window_;
};

int main(int argc, char** argv) { return plumb::test::runGuiTest<GuiNetworkTest>(argc, argv); }

#include "test_gui_network.moc"
