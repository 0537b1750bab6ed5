// The quality panel (issue 13): the verdict level in words on a coloured band, every figure of
// the report in the table, every candidate placement listed; for the three levels, from
// reports built by the core's assessRegistration.
#include <QApplication>
#include <QLabel>
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
