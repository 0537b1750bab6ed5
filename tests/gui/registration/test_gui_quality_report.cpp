// The quality panel (issue 13): the verdict level in words on a coloured band, every figure of
// the report in the table, every candidate placement listed; for the three levels, from
// reports built by the core's assessRegistration.
#include <QApplication>
#include <QLabel>
#include <QTableWidget>
#include <QTest>

#include "registration/auto/registration_pipeline.hpp"
#include "ui/registration/quality_report_view.hpp"

using namespace plumb;
using namespace plumb::ui;

namespace {

/// A refinement that found every direction held (resistances well above the thresholds).
RefineResult goodRefinement(const RigidTransform& t) {
  RefineResult r;
  r.transform = t;
  r.converged = true;
  r.rms = 0.006;
  r.overlap = 0.72;
  r.inliers = 12000;
  r.fit_cost = 0.27;
  r.normal_matrix = Eigen::Matrix<double, 6, 6>::Identity();
  r.direction_resistance.fill(0.4);
  return r;
}

GlobalRegistrationResult globalResult(RegistrationStatus status) {
  GlobalRegistrationResult g;
  g.status = status;
  g.method = "planes";
  g.message = "test";
  g.transform = RigidTransform(Eigen::Matrix3d::Identity(), Eigen::Vector3d(1, 2, 0));
  g.score = 60.0;
  g.score_unit = "m^2";
  g.runner_up = Hypothesis{RigidTransform(), 40.0, "half turn"};
  g.relative_gap = 0.33;
  g.hypotheses_evaluated = 48;
  g.figures = {{"test figure", 1.25}};
  return g;
}

PipelineResult pipelineResult(RegistrationStatus status, bool refined) {
  PipelineResult p;
  p.global = globalResult(status);
  p.method_used = "planes";
  const RefineResult r = goodRefinement(p.global.transform);
  PlacementCandidate chosen = makeCandidate({p.global.transform, 60.0, "a"}, refined ? &r : nullptr,
                                            "chosen");
  PlacementCandidate other = makeCandidate(*p.global.runner_up, refined ? &r : nullptr,
                                           status == RegistrationStatus::Ambiguous ? "competing"
                                                                                   : "worse");
  other.figures = {{"free-space contradictions", 12.0}};
  p.candidates = {chosen, other};
  p.report = assessRegistration(p.global, refined ? &r : nullptr, {}, p.candidates);
  return p;
}

bool hasFigure(const QualityReportView& v, const QString& name) {
  for (int i = 0; i < v.rowCount(); ++i)
    if (v.figureName(i) == name) return true;
  return false;
}

}  // namespace

class GuiQualityReportTest : public QObject {
  Q_OBJECT
 private slots:
  void usableIsGreenWithEveryFigure() {
    QualityReportView view;
    const PipelineResult r = pipelineResult(RegistrationStatus::Success, true);
    QCOMPARE(r.report.level, VerdictLevel::Usable);
    view.showResult(r);
    QCOMPARE(view.level(), QString("USABLE"));
    QVERIFY(view.findChild<QLabel*>("verdictLevel")->styleSheet().contains("#2e7d32"));
    for (const char* name : {"Verdict level", "Method", "Status", "Rotation (deg)",
                             "Translation (m)", "Hypotheses evaluated", "Features matched",
                             "Feature RMS (m)", "Point RMS (m)", "Overlap", "Point inliers",
                             "Refinement shift (m)", "Refinement rotation (deg)",
                             "Slide resistance", "Runner-up score", "Runner-up gap", "test figure"})
      QVERIFY2(hasFigure(view, name), name);
    QCOMPARE(view.candidateCount(), 2);
    QCOMPARE(view.candidateRole(0), QString("chosen"));
    QCOMPARE(view.candidateRole(1), QString("worse"));
  }

  // At the dock's width every value is readable: the value column gets room, long values
  // wrap onto taller rows, every cell's tooltip holds the whole row; counts print without
  // decimals, flags as yes/no, and the internal timings come last (before: one letter of each
  // value showed, warnings were cut off, "matched openings 6.000" amid "seconds ...").
  void figuresAreReadableAtTheDockWidth() {
    QualityReportView view;
    view.resize(320, 600);
    PipelineResult r = pipelineResult(RegistrationStatus::Success, false);
    r.report.figures = {{"seconds features", 1.5}, {"matched openings", 6.0},
                        {"wall thickness measured", 1.0}, {"wall thickness (m)", 0.31},
                        {"façade directions with matched openings (long name)", 2.0}};
    r.report.warnings.push_back(
        "the refinement was switched off: the placement rests on the features alone, check "
        "the overlap of the two data sets visually before using it");
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    view.showResult(r);
    auto* table = view.findChild<QTableWidget*>("qualityFigures");
    QVERIFY(table);
    const int width = table->viewport()->width();
    QVERIFY2(table->columnWidth(1) >= width / 2 - 2,
             qPrintable(QString("%1 of %2").arg(table->columnWidth(1)).arg(width)));
    for (int row = 0; row < table->rowCount(); ++row) {
      const QString name = view.figureName(row), value = view.figureValue(row);
      QCOMPARE(table->item(row, 1)->toolTip(), name + ": " + value);
      QCOMPARE(table->item(row, 0)->toolTip(), name + ": " + value);
      // The row is as tall as the value wrapped in its column.
      const QRect needed = table->fontMetrics().boundingRect(
          QRect(0, 0, table->columnWidth(1) - 8, 10000), Qt::TextWordWrap, value);
      QVERIFY2(table->rowHeight(row) >= needed.height(), qPrintable(name));
    }
    QStringList names;
    for (int row = 0; row < table->rowCount(); ++row) names << view.figureName(row);
    QCOMPARE(view.figureValue(int(names.indexOf("matched openings"))), QString("6"));
    QCOMPARE(view.figureValue(int(names.indexOf("wall thickness measured"))), QString("yes"));
    QCOMPARE(view.figureValue(int(names.indexOf("wall thickness (m)"))), QString("0.310"));
    QVERIFY(!names.contains("seconds features"));
    QCOMPARE(names.last(), QString("Time: features"));
    QCOMPARE(view.figureValue(int(names.size()) - 1), QString("1.50 s"));
  }

  void checkVisuallyIsAmberAndListsTheWarning() {
    QualityReportView view;
    const PipelineResult r = pipelineResult(RegistrationStatus::Success, false);  // refinement off
    QCOMPARE(r.report.level, VerdictLevel::CheckVisually);
    view.showResult(r);
    QCOMPARE(view.level(), QString("CHECK VISUALLY"));
    QVERIFY(view.findChild<QLabel*>("verdictLevel")->styleSheet().contains("#f0b400"));
    QVERIFY(hasFigure(view, "Warning"));
    QVERIFY(!hasFigure(view, "Point RMS (m)"));
  }

  void ambiguousIsRedAndListsBothCandidates() {
    QualityReportView view;
    const PipelineResult r = pipelineResult(RegistrationStatus::Ambiguous, true);
    QCOMPARE(r.report.level, VerdictLevel::Failed);
    view.showResult(r);
    QCOMPARE(view.level(), QString("FAILED OR AMBIGUOUS"));
    QVERIFY(view.findChild<QLabel*>("verdictLevel")->styleSheet().contains("#c62828"));
    QVERIFY(view.verdict().contains("FAILED (ambiguous)"));
    QVERIFY(!hasFigure(view, "Translation (m)"));  // no transform is given
    QCOMPARE(view.candidateCount(), 2);
    QCOMPARE(view.candidateRole(1), QString("competing"));
    view.clear();
    QCOMPARE(view.candidateCount(), 0);
    QVERIFY(view.level().isEmpty());
  }
};

int main(int argc, char** argv) {
  QApplication app(argc, argv);
  GuiQualityReportTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "test_gui_quality_report.moc"
