#include "ui/registration/quality_report_view.hpp"

#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>

#include <cmath>
#include <cstdint>

#include "registration/auto/registration_pipeline.hpp"

namespace plumb::ui {

namespace {
QString num(double v, int d = 4) { return QString::number(v, 'f', d); }

QString vec(const Eigen::Vector3d& v, int d = 3) {
  return QString("%1, %2, %3").arg(num(v.x(), d), num(v.y(), d), num(v.z(), d));
}

/// Background and text colours of the level band.
QString levelStyle(VerdictLevel level) {
  switch (level) {
    case VerdictLevel::Usable: return "background:#2e7d32;color:white;";
    case VerdictLevel::CheckVisually: return "background:#f0b400;color:black;";
    case VerdictLevel::Failed: return "background:#c62828;color:white;";
  }
  return {};
}

QTableWidget* makeTable(QWidget* parent, const QStringList& headers, const char* name) {
  auto* t = new QTableWidget(0, int(headers.size()), parent);
  t->setObjectName(name);
  t->setHorizontalHeaderLabels(headers);
  t->horizontalHeader()->setStretchLastSection(true);
  t->setWordWrap(true);  // long values wrap onto more lines instead of being cut
  t->setTextElideMode(Qt::ElideNone);
  t->verticalHeader()->hide();
  t->setEditTriggers(QAbstractItemView::NoEditTriggers);
  return t;
}

/// A method figure as a reader expects it: counts without decimals, flags ("... measured") as
/// yes/no, other values with three decimals.
QString figureText(const std::string& name, double value) {
  const bool flag = name.size() > 9 && name.compare(name.size() - 9, 9, " measured") == 0;
  if (flag && (value == 0.0 || value == 1.0)) return value != 0.0 ? QObject::tr("yes") : QObject::tr("no");
  if (std::abs(value) < 1e15 && value == std::round(value)) return QString::number(std::int64_t(value));
  return num(value, 3);
}

/// Internal timings ("seconds features") are listed apart, last.
bool isTiming(const std::string& name) { return name.rfind("seconds ", 0) == 0; }

QString cell(const QTableWidget* t, int row, int col) {
  const QTableWidgetItem* item = t->item(row, col);
  return item ? item->text() : QString();
}
}  // namespace

QualityReportView::QualityReportView(QWidget* parent)
    : QWidget(parent),
      level_(new QLabel(this)),
      verdict_(new QLabel(this)),
      table_(makeTable(this, {tr("Figure"), tr("Value")}, "qualityFigures")),
      candidates_(makeTable(this,
                            {tr("Role"), tr("Rotation (deg)"), tr("Translation (m)"),
                             tr("Feature score"), tr("Overlap"), tr("Point RMS (m)"),
                             tr("Inliers"), tr("Fit cost"), tr("Evidence")},
                            "candidatePlacements")) {
  setObjectName("qualityReport");
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  level_->setObjectName("verdictLevel");
  level_->setAlignment(Qt::AlignCenter);
  QFont f = level_->font();
  f.setBold(true);
  f.setPointSizeF(f.pointSizeF() * 1.4);
  level_->setFont(f);
  layout->addWidget(level_);
  verdict_->setObjectName("verdict");
  verdict_->setWordWrap(true);
  verdict_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  layout->addWidget(verdict_);
  table_->setMinimumHeight(140);
  layout->addWidget(table_, 2);
  layout->addWidget(new QLabel(tr("Candidate placements"), this));
  candidates_->setMinimumHeight(70);
  layout->addWidget(candidates_, 1);
  clear();
}

void QualityReportView::clear(const QString& note) {
  level_->clear();
  level_->setStyleSheet({});
  verdict_->setText(note.isEmpty() ? tr("<i>No registration yet.</i>") : note);
  table_->setRowCount(0);
  candidates_->setRowCount(0);
}

QString QualityReportView::verdict() const { return verdict_->text(); }
QString QualityReportView::level() const { return level_->text(); }
int QualityReportView::rowCount() const { return table_->rowCount(); }
QString QualityReportView::figureName(int row) const { return cell(table_, row, 0); }
QString QualityReportView::figureValue(int row) const { return cell(table_, row, 1); }
int QualityReportView::candidateCount() const { return candidates_->rowCount(); }
QString QualityReportView::candidateRole(int row) const { return cell(candidates_, row, 0); }

void QualityReportView::addRow(const QString& name, const QString& value) {
  const int r = table_->rowCount();
  table_->insertRow(r);
  for (int c = 0; c < 2; ++c) {
    auto* item = new QTableWidgetItem(c == 0 ? name : value);
    item->setToolTip(name + ": " + value);  // the whole text, however narrow the dock
    table_->setItem(r, c, item);
  }
}

void QualityReportView::addVisibilityRows(const VisibilitySummary& v) {
  if (!v.computed) return;
  auto pct = [](double r) { return QString::number(r * 100.0, 'f', 1) + " %"; };
  for (const VisibilityEvidence* e : {&v.source_in_target, &v.target_in_source}) {
    if (e->what.empty()) continue;
    const QString name = tr("Free space: %1").arg(QString::fromStdString(e->what));
    if (!e->available)
      addRow(name, tr("no evidence (%1)").arg(QString::fromStdString(e->missing_reason)));
    else
      addRow(name,
             tr("%1 contradicting of %2 visible").arg(pct(e->contradiction_ratio)).arg(e->visible));
  }
  if (v.expected_overlap >= 0) addRow(tr("Expected overlap (visibility)"), pct(v.expected_overlap));
  if (v.unexplained_structure >= 0)
    addRow(tr("Unexplained structure (large planes)"), pct(v.unexplained_structure));
}

void QualityReportView::showResult(const PipelineResult& result) {
  const QualityReport& q = result.report;
  level_->setText(QString(verdictLevelWords(q.level)).toUpper());
  level_->setStyleSheet(levelStyle(q.level) + "padding:4px;border-radius:3px;");
  level_->setToolTip(tr("Exit code of plumb-cli register: %1").arg(verdictExitCode(q.level)));
  verdict_->setText(QString::fromStdString(q.verdict).toHtmlEscaped());
  table_->setRowCount(0);
  addFigures(result);
  fitColumns();
  addCandidates(q);
}

void QualityReportView::addFigures(const PipelineResult& result) {
  const QualityReport& q = result.report;
  addRow(tr("Verdict level"), QString("%1 (exit %2)")
                                  .arg(verdictLevelWords(q.level))
                                  .arg(verdictExitCode(q.level)));
  addRow(tr("Method"), QString::fromStdString(result.method_used));
  addRow(tr("Status"), QString::fromStdString(q.status));
  if (q.success) {
    addRow(tr("Rotation (deg)"), num(q.transform.rotationAngleDeg(), 3));
    addRow(tr("Translation (m)"), vec(q.transform.translation()));
  }
  addRow(tr("Global score (%1)").arg(QString::fromStdString(q.score_unit)), num(q.global_score, 3));
  addRow(tr("Hypotheses evaluated"), QString::number(q.hypotheses));
  addRow(tr("Features matched"), QString("%1 of %2 (target %3)")
                                     .arg(q.inlier_features)
                                     .arg(q.source_features)
                                     .arg(q.target_features));
  addRow(tr("Feature RMS (m)"), num(q.feature_rms));
  if (q.refined) {
    addRow(tr("Point RMS (m)"), num(q.point_rms));
    addRow(tr("Overlap"), QString::number(q.overlap_ratio * 100.0, 'f', 1) + " %");
    addRow(tr("Point inliers"), QString::number(q.point_inliers));
    addRow(tr("Refinement shift (m)"), num(q.refinement_shift));
    addRow(tr("Refinement rotation (deg)"), num(q.refinement_rotation));
    QStringList resistance;
    for (double r : q.direction_resistance) resistance << num(r, 3);
    addRow(tr("Slide resistance"), resistance.join(", "));
  }
  if (q.has_runner_up) {
    addRow(tr("Runner-up score"), num(q.runner_up_score, 3));
    addRow(tr("Runner-up gap"), QString::number(q.relative_gap * 100.0, 'f', 1) + " %");
  }
  addVisibilityRows(q.visibility);
  for (const auto& w : q.weak_directions) addRow(tr("Weak"), QString::fromStdString(w.description));
  for (const auto& [name, value] : q.figures)
    if (!isTiming(name)) addRow(QString::fromStdString(name), figureText(name, value));
  for (const auto& w : q.warnings) addRow(tr("Warning"), QString::fromStdString(w));
  for (const auto& [name, value] : q.figures)
    if (isTiming(name))
      addRow(tr("Time: %1").arg(QString::fromStdString(name.substr(8))), num(value, 2) + " s");
}

void QualityReportView::addCandidates(const QualityReport& q) {
  candidates_->setRowCount(0);
  for (const auto& c : q.candidates) {
    const int r = candidates_->rowCount();
    candidates_->insertRow(r);
    QStringList evidence;
    for (const auto& [name, value] : c.figures)
      evidence << QString::fromStdString(name) + " " + num(value, 3);
    const QStringList cells = {QString::fromStdString(c.role),
                               num(c.transform.rotationAngleDeg(), 3),
                               vec(c.transform.translation()),
                               num(c.feature_score, 3),
                               c.refined ? QString::number(c.overlap * 100.0, 'f', 1) + " %" : "-",
                               c.refined ? num(c.point_rms) : "-",
                               c.refined ? QString::number(c.inliers) : "-",
                               c.refined ? num(c.fit_cost) : "-",
                               evidence.join("; ")};
    for (int k = 0; k < cells.size(); ++k) candidates_->setItem(r, k, new QTableWidgetItem(cells[k]));
  }
  candidates_->resizeColumnsToContents();
}

void QualityReportView::fitColumns() {
  // Names take what they need up to 45 % of the width; values get the rest and wrap.
  table_->resizeColumnToContents(0);
  const int most = table_->viewport()->width() * 45 / 100;
  if (table_->columnWidth(0) > most) table_->setColumnWidth(0, most);
  table_->resizeRowsToContents();
}

void QualityReportView::resizeEvent(QResizeEvent* event) {
  QWidget::resizeEvent(event);
  if (table_->rowCount() > 0) fitColumns();
}

}  // namespace plumb::ui
