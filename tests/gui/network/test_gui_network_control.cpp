// The Network dock against what plumb-cli network does with --reference NAME and --control /
// --targets / --crs (docs/NETWORK.md "Control points"), on the campaign of test_gui_network
// with 3 control and 2 check targets in UTM zone 32N (plumb-cli simulate --control-points 3,2,
// as tests/integration/network/test_cli_network.cpp simulateControlledCampaign): the reference
// combo offers every station; bad control input is refused before any task starts, with the
// core's message naming the file and the line; a named reference keeps its file pose bit for
// bit; the georeferenced run places every station in the grid within the target, and
// the dock's residuals are the report's; a re-run keeps the georeference. One campaign for the
// whole suite (the slots run in order).
#include <QDoubleSpinBox>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QTabWidget>
#include <QTableWidget>
#include <QTest>

#include <fstream>

#include "common/error.hpp"
#include "gui/open_window.hpp"
#include "support/cli_runner.hpp"
#include "support/network_truth.hpp"
#include "support/two_room_campaign.hpp"
#include "ui/network/control_settings.hpp"
#include "ui/network/georeference_view.hpp"
#include "ui/network/network_panel.hpp"
#include "ui/network/network_plan_view.hpp"
#include "ui/network/network_runner.hpp"
#include "ui/network/reference_combo.hpp"
#include "ui/network/station_table.hpp"
#include "ui/panels/log_panel.hpp"
#include "ui/tasks/task_manager.hpp"

using namespace plumb;
using namespace plumb::ui;

namespace {
constexpr int kRunTimeoutMs = 300000;
constexpr int kAdjustTimeoutMs = 60000;
constexpr std::size_t kStations = 5;
constexpr std::size_t kPoints = 5;  // 3 control, 2 check
}  // namespace

class GuiNetworkControlTest : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase() {
    dir_ = test::scratchDir("gui_network_control");
    const auto r = test::simulateTwoRoomCampaign(dir_, 5, "--control-points 3,2 --grid 651000,6860000,40 --crs EPSG:32632");
    QVERIFY2(r.exit_code == 0, r.err.c_str());
    QVERIFY(std::filesystem::exists(dir_ / "sim/control.csv") && std::filesystem::exists(dir_ / "sim/targets.csv"));
    test::openWindowWithFiles(window_, {QString::fromStdString((dir_ / "sim/indoor.e57").string())});
    QVERIFY(window_);
    QVERIFY(window_->context().network);
  }
  void cleanupTestCase() {
    if (window_)
      QVERIFY(QTest::qWaitFor([&] { return window_->context().tasks.runningCount() == 0; }, kRunTimeoutMs));
    window_.reset();
  }

  // "Reference" offers the first station, then every station by the name the run gives it.
  void referenceOffersEveryStation() {
    ReferenceCombo& combo = panel().reference();
    QCOMPARE(combo.count(), int(1 + kStations));
    QCOMPARE(combo.currentIndex(), 0);
    QVERIFY(combo.station().empty());
    const auto truth = test::readJsonFile(dir_ / "sim/truth.json");
    QCOMPARE(truth["scans"].size(), kStations);
    for (const auto& s : truth["scans"])
      QVERIFY2(combo.findData(QString::fromStdString(s["scan"].get<std::string>())) > 0,
               s["scan"].get<std::string>().c_str());
  }

  // The grid field takes a scale factor as a number, a CRS (PROJ's factor), or nothing (1).
  void gridFieldTakesAFactorOrACrs() {
    ControlSettings s{path("sim/control.csv"), path("sim/targets.csv"), "0.99988", 0.003};
    const auto names = stationNames();
    QCOMPARE(loadControlSurvey(s, names)->grid.scale_factor, 0.99988);
    QCOMPARE(loadControlSurvey(s, names)->sigma, 0.003);
    s.grid = "";
    QCOMPARE(loadControlSurvey(s, names)->grid.scale_factor, 1.0);
    s.grid = " EPSG:32632 ";
    const auto survey = loadControlSurvey(s, names);
    QCOMPARE(QString::fromStdString(survey->grid.crs), QString("EPSG:32632"));
    QVERIFY2(std::abs(survey->grid.scale_factor - 0.99988) < 1e-5, qPrintable(QString::number(survey->grid.scale_factor)));
    QVERIFY(!loadControlSurvey(ControlSettings{}, names));  // no files: no control
  }

  // A letter in a coordinate: the core's error, naming the file and the line, is logged and no
  // run starts. So for a target of an unknown station, a grid factor out of range, a lone file.
  void badControlInputRefusesTheRun() {
    writeBadControl("bad.csv", 3);
    setControl(path("bad.csv"), path("sim/targets.csv"), "EPSG:32632");
    expectRefused({"bad.csv", "line 3"});
    std::ofstream(dir_ / "bad-targets.csv") << "# station, point, x, y, z\ntls-0,CP1,1,2,3\ntls-9,CP2,1,2,3\n";
    setControl(path("sim/control.csv"), path("bad-targets.csv"), "EPSG:32632");
    expectRefused({"bad-targets.csv", "line 3", "no station is named 'tls-9'"});
    setControl(path("sim/control.csv"), path("sim/targets.csv"), "1.5");
    expectRefused({"(0.9, 1.1)"});
    setControl(path("sim/control.csv"), "", "");
    expectRefused({"give both"});
  }

  // A reference no station has (as plumb-cli network --reference nowhere) is refused, naming them.
  void unknownReferenceIsRefused() {
    window_->context().log.clear();
    QVERIFY(!runner().run(nullptr, "nowhere"));
    QCOMPARE(window_->context().tasks.runningCount(), 0);
    QVERIFY2(log().contains("no station is named 'nowhere'") && log().contains("tls-0"), qPrintable(log()));
  }

  // A named station (not the first) is the reference: without control it keeps its file pose
  // bit for bit, the network is in its frame, and the others are placed there as the truth says.
  void namedReferenceKeepsItsFilePose() {
    setControl("", "", "EPSG:32632");  // the grid field alone is no control survey
    ReferenceCombo& combo = panel().reference();
    const std::size_t ref = 2;
    const QString name = combo.itemData(int(ref) + 1).toString();
    QVERIFY(combo.chooseStation(name));
    QCOMPARE(combo.station(), name.toStdString());
    runAndWait();
    const auto session = runner().session();
    QCOMPARE((*session->stations)[ref].name, name.toStdString());
    QCOMPARE(session->result->reference, ref);
    QCOMPARE(session->report["reference"].get<std::string>(), name.toStdString());
    QVERIFY(session->result->adjustment.poses[ref]->matrix() == (*session->stations)[ref].file_pose.matrix());
    QVERIFY(!session->control);
    QVERIFY(!session->report.contains("georeference"));
    QVERIFY(panel().georeference().status().startsWith("No control points"));
    QCOMPARE(panel().georeference().points().rowCount(), 0);
    QCOMPARE(panel().plan().frameLabel(), QString("frame of station %1").arg(name));
    for (std::size_t i = 0; i < kStations; ++i)  // the combo's order is the run's
      QCOMPARE(combo.itemData(int(i) + 1).toString().toStdString(), (*session->stations)[i].name);
    expectWithinTargetOfTruth(session->report, false);
  }

  // The control points georeference the network: every station in the grid within 5 mm and
  // 0.02 deg of the truth; the dock shows the report's status, factor and residuals.
  void controlPointsGeoreferenceTheNetwork() {
    panel().reference().setCurrentIndex(0);
    setControl(path("sim/control.csv"), path("sim/targets.csv"), "EPSG:32632");
    runAndWait();
    const auto session = runner().session();
    QVERIFY(session->control);
    QVERIFY2(session->result->complete(), qPrintable(panel().georeference().status()));
    QVERIFY(session->report.contains("georeference"));
    const auto& g = session->report["georeference"];
    QVERIFY(g["done"].get<bool>());
    QCOMPARE(session->report["reference"].get<std::string>(), std::string("control points"));
    QVERIFY(panel().georeference().status().startsWith("Georeference done: "));
    const double k = g["scale_factor"].get<double>();
    QVERIFY2(std::abs(k - 0.99988) < 1e-5, qPrintable(QString::number(k)));
    QVERIFY(panel().georeference().scaleFactor().contains(scaleFactorText(k)));
    QVERIFY(panel().georeference().scaleFactor().contains("EPSG:32632"));
    QCOMPARE(panel().plan().frameLabel(), QString("grid (control points)"));
    expectResidualsShown(g);
    expectWithinTargetOfTruth(session->report, true);
    // A station that sees 3 control points itself is confirmed by them; the state says so.
    int settled = 0;
    for (std::size_t i = 0; i < session->report["stations"].size(); ++i) {
      const bool confirmed = session->report["stations"][i].value("settled_by_control", false);
      settled += confirmed;
      QCOMPARE(panel().stations().item(int(i), StationTable::State)->toolTip().startsWith("Confirmed"), confirmed);
    }
    QVERIFY(settled > 0);
    auto* page = panel().findChild<QWidget*>("networkControlPage");
    QVERIFY(page);
    panel().findChild<QTabWidget*>()->setCurrentWidget(page);
    panel().show();
    const auto shot = dir_ / "network-control.png";  // to look at when the table is in doubt
    QVERIFY(page->grab().save(QString::fromStdString(shot.string())));
  }

  // Re-run adjustment passes the control survey on: still georeferenced, the table follows.
  void rerunKeepsTheGeoreference() {
    const auto before = runner().session()->report["georeference"];
    QSignalSpy adjusted(&runner(), &NetworkRunner::adjusted);
    QVERIFY(runner().rerunAdjustment());
    QVERIFY(adjusted.wait(kAdjustTimeoutMs));
    QVERIFY2(adjusted.at(0).at(0).toBool(), qPrintable(log()));
    QVERIFY(runner().session()->report.contains("georeference"));  // the re-run had the control survey
    const auto& g = runner().session()->report["georeference"];
    QVERIFY(g["done"].get<bool>());
    QCOMPARE(g["points"].size(), before["points"].size());
    QCOMPARE(panel().plan().frameLabel(), QString("grid (control points)"));
    expectResidualsShown(g);
    expectWithinTargetOfTruth(runner().session()->report, true);
  }

  // Two control points (CP3 made a check point) cannot hold the frame: the dock says so and why,
  // still lists every point, and the plan is in the reference's frame, not the grid.
  void twoControlPointsDoNotGeoreference() {
    std::ifstream in(dir_ / "sim/control.csv");
    std::ofstream two(dir_ / "two.csv");
    for (std::string line; std::getline(in, line);)
      two << (line.rfind("CP3,", 0) == 0 ? line.substr(0, line.rfind(',')) + ",check" : line) << "\n";
    two.close();
    setControl(path("two.csv"), path("sim/targets.csv"), "EPSG:32632");
    runAndWait();
    const auto session = runner().session();
    QVERIFY(session->report.contains("georeference"));
    QVERIFY(!session->report["georeference"]["done"].get<bool>());
    QVERIFY(!session->result->complete());
    const QString status = panel().georeference().status();
    QVERIFY2(status.startsWith("Not georeferenced: ") && status.contains("3 are needed"), qPrintable(status));
    QCOMPARE(panel().georeference().points().rowCount(), int(kPoints));
    QCOMPARE(panel().georeference().points().item(2, GeoreferenceView::Role)->text(), QString("check"));
    QCOMPARE(panel().plan().frameLabel(),
             QString("frame of station %1").arg(QString::fromStdString((*session->stations)[0].name)));
  }

 private:
  NetworkPanel& panel() { return *window_->context().network; }
  NetworkRunner& runner() { return panel().runner(); }
  QString log() { return window_->context().log.toPlainText(); }
  std::string path(const char* name) { return (dir_ / name).string(); }

  std::vector<std::string> stationNames() {
    std::vector<std::string> names;
    for (int i = 1; i <= int(kStations); ++i) names.push_back(panel().reference().itemData(i).toString().toStdString());
    return names;
  }

  /// Types the control survey into the dock's Control tab, as the surveyor does.
  void setControl(const std::string& control, const std::string& targets, const QString& grid) {
    for (auto [name, text] : {std::pair{"networkControlFile", QString::fromStdString(control)},
                              std::pair{"networkTargetsFile", QString::fromStdString(targets)},
                              std::pair{"networkGridScale", grid}}) {
      auto* edit = panel().findChild<QLineEdit*>(name);
      QVERIFY2(edit, name);
      edit->setText(text);
    }
    QCOMPARE(runner().control().control, control);
    QCOMPARE(runner().control().targets, targets);
  }

  /// control.csv with a letter in the first coordinate of line `line`.
  void writeBadControl(const char* name, int line) {
    std::ifstream in(dir_ / "sim/control.csv");
    std::ofstream out(dir_ / name);
    int n = 0;
    for (std::string text; std::getline(in, text);) {
      if (++n == line) text.replace(text.find(',') + 1, 1, "x");
      out << text << "\n";
    }
    QVERIFY2(n >= line, "control.csv is shorter than expected");
  }

  void expectRefused(std::initializer_list<const char*> words) {
    window_->context().log.clear();
    QSignalSpy busy(&runner(), &NetworkRunner::busyChanged);
    auto* run = panel().findChild<QPushButton*>("networkRun");
    QVERIFY(run && run->isEnabled());
    QTest::mouseClick(run, Qt::LeftButton);
    QCOMPARE(busy.count(), 0);
    QCOMPARE(window_->context().tasks.runningCount(), 0);
    QVERIFY(!runner().busy());
    for (const char* w : words) QVERIFY2(log().contains(w), qPrintable(QString("'%1' not in: %2").arg(w, log())));
  }

  void runAndWait() {
    QSignalSpy finished(&runner(), &NetworkRunner::finished);
    auto* run = panel().findChild<QPushButton*>("networkRun");
    QVERIFY(run && run->isEnabled());
    QTest::mouseClick(run, Qt::LeftButton);
    QVERIFY2(runner().busy(), qPrintable(log()));
    QVERIFY(finished.wait(kRunTimeoutMs));
    QVERIFY2(finished.at(0).at(0).toBool(), qPrintable(log()));
  }

  /// Every row of the residual table is the report's point, its figures the report's in mm.
  void expectResidualsShown(const nlohmann::json& g) {
    const QTableWidget& table = panel().georeference().points();
    QCOMPARE(g["points"].size(), kPoints);
    QCOMPARE(table.rowCount(), int(kPoints));
    int checks = 0;
    for (int row = 0; row < table.rowCount(); ++row) {
      const auto& p = g["points"][std::size_t(row)];
      const auto text = [&](int column) { return table.item(row, column)->text(); };
      QCOMPARE(text(GeoreferenceView::Point).toStdString(), p["name"].get<std::string>());
      QCOMPARE(text(GeoreferenceView::Role).toStdString(), p["role"].get<std::string>());
      checks += p["role"] == "check";
      QVERIFY2(p["observations"].get<int>() > 0, p["name"].get<std::string>().c_str());
      QCOMPARE(text(GeoreferenceView::Residual), residualMm(p["residual_m"].get<double>()));
      for (int a = 0; a < 3; ++a)
        QCOMPARE(text(GeoreferenceView::East + a), residualMm(p["residual_grid_m"][std::size_t(a)].get<double>()));
      bool ok = false;
      const double mm = text(GeoreferenceView::Residual).toDouble(&ok);
      QVERIFY(ok);
      QVERIFY2(mm < 5.0, qPrintable(QString("%1: %2 mm").arg(text(GeoreferenceView::Point)).arg(mm)));
    }
    QCOMPARE(checks, 2);
  }

  /// The report's poses against truth.json (network_truth.hpp): in the grid frame when
  /// georeferenced, else in the reference's file frame.
  void expectWithinTargetOfTruth(const nlohmann::json& report, bool georeferenced) {
    const auto truth = test::readJsonFile(dir_ / "sim/truth.json");
    QCOMPARE(test::georeferencedFrame(truth, report).has_value(), georeferenced);
    const auto errors = test::reportErrors(truth, report);
    QCOMPARE(errors.size(), kStations);
    for (const auto& e : errors) {
      QVERIFY2(e.placed, e.name.c_str());
      QVERIFY2(e.translation_m < 0.005, qPrintable(QString("%1: %2 m").arg(e.name.c_str()).arg(e.translation_m)));
      QVERIFY2(e.rotation_deg < 0.02, qPrintable(QString("%1: %2 deg").arg(e.name.c_str()).arg(e.rotation_deg)));
    }
  }

  std::filesystem::path dir_;
  std::unique_ptr<MainWindow> window_;
};

int main(int argc, char** argv) { return plumb::test::runGuiTest<GuiNetworkControlTest>(argc, argv); }

#include "test_gui_network_control.moc"
