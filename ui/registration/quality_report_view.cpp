#include "ui/registration/quality_report_view.hpp"

#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>

#include "registration/auto/registration_pipeline.hpp"

namespace plumb::ui {

QualityReportView::QualityReportView(QWidget* parent)
    : QWidget(parent), verdict_(new QLabel(this)), table_(new QTableWidget(0, 2, this)) {
  setObjectName("qualityReport");
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  verdict_->setObjectName("verdict");
  verdict_->setWordWrap(true);
  verdict_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  layout->addWidget(verdict_);
  table_->setHorizontalHeaderLabels({tr("Figure"), tr("Value")});
  table_->horizontalHeader()->setStretchLastSection(true);
  table_->verticalHeader()->hide();
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->setMinimumHeight(140);
  layout->addWidget(table_, 1);
  clear();
}

void QualityReportView::clear() {
  verdict_->setText(tr("<i>No registration yet.</i>"));
  table_->setRowCount(0);
}

QString QualityReportView::verdict() const { return verdict_->text(); }
int QualityReportView::rowCount() const { return table_->rowCount(); }

void QualityReportView::addRow(const QString& name, const QString& value) {
  const int r = table_->rowCount();
  table_->insertRow(r);
  table_->setItem(r, 0, new QTableWidgetItem(name));
  table_->setItem(r, 1, new QTableWidgetItem(value));
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
}

void QualityReportView::showResult(const PipelineResult& result) {
  const QualityReport& q = result.report;
  const char* color = !q.success ? "#d04040" : q.warnings.empty() ? "#3a9a3a" : "#c08a10";
  verdict_->setText(QString("<span style='color:%1'><b>%2</b></span>")
                        .arg(color, QString::fromStdString(q.verdict).toHtmlEscaped()));
  table_->setRowCount(0);
  auto num = [](double v, int d = 4) { return QString::number(v, 'f', d); };
  addRow(tr("Method"), QString::fromStdString(result.method_used));
  addRow(tr("Status"), QString::fromStdString(q.status));
  if (q.success) {
    addRow(tr("Rotation (deg)"), num(q.transform.rotationAngleDeg(), 3));
    const auto t = q.transform.translation();
    addRow(tr("Translation (m)"), QString("%1, %2, %3").arg(num(t.x(), 3), num(t.y(), 3), num(t.z(), 3)));
  }
  addRow(tr("Features matched"), QString("%1 of %2 (target %3)")
                                     .arg(q.inlier_features)
                                     .arg(q.source_features)
                                     .arg(q.target_features));
  addRow(tr("Feature RMS (m)"), num(q.feature_rms));
  if (q.refined) {
    addRow(tr("Point RMS (m)"), num(q.point_rms));
    addRow(tr("Overlap"), QString::number(q.overlap_ratio * 100.0, 'f', 1) + " %");
    addRow(tr("Refinement shift (m)"), num(q.refinement_shift));
  }
  addVisibilityRows(q.visibility);
  if (q.has_runner_up) addRow(tr("Runner-up gap"), QString::number(q.relative_gap * 100.0, 'f', 1) + " %");
  for (const auto& w : q.weak_directions) addRow(tr("Weak"), QString::fromStdString(w.description));
  for (const auto& [name, value] : q.figures) addRow(QString::fromStdString(name), num(value, 3));
  for (const auto& w : q.warnings) addRow(tr("Warning"), QString::fromStdString(w));
  table_->resizeColumnToContents(0);
}

}  // namespace plumb::ui
