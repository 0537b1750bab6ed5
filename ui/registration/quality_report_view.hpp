#pragma once
// The quality report of the last registration: the verdict level in words on a coloured band
// (green usable, amber check visually, red failed or ambiguous: words, not colour only), the
// verdict paragraph, a table of every figure of the report (method, transform, RMS, overlap,
// features, runner-up gap, slide resistances, weak directions, method figures, warnings) and a
// table of the candidate placements (role, transform, feature score, refined overlap, RMS,
// inliers, fit cost and any further evidence figures). Values wrap (no cut-off text at the
// dock's width) and every cell's tooltip holds its whole row; counts print without decimals,
// flags as yes/no, internal timings last.
#include <QWidget>

class QLabel;
class QTableWidget;

namespace plumb {
struct PipelineResult;
struct VisibilitySummary;
struct QualityReport;
}

namespace plumb::ui {

class QualityReportView : public QWidget {
  Q_OBJECT
 public:
  explicit QualityReportView(QWidget* parent = nullptr);
  void showResult(const PipelineResult& result);
  /// No result shown; `note` (rich text) says why, e.g. that it was undone.
  void clear(const QString& note = {});
  QString verdict() const;
  /// The level band's text, e.g. "USABLE", "CHECK VISUALLY", "FAILED OR AMBIGUOUS".
  QString level() const;
  /// Figure rows (name, value), for tests.
  int rowCount() const;
  /// Figure `row`'s name and value, for tests.
  QString figureName(int row) const;
  QString figureValue(int row) const;
  /// Candidate placement rows, for tests.
  int candidateCount() const;
  QString candidateRole(int row) const;

 protected:
  void resizeEvent(QResizeEvent* event) override;

 private:
  void fitColumns();
  void addRow(const QString& name, const QString& value);
  /// Free-space evidence: each direction's contradiction ratio (or why there is none) and
  /// the expected overlap.
  void addVisibilityRows(const VisibilitySummary& visibility);
  void addFigures(const PipelineResult& result);
  void addCandidates(const QualityReport& report);
  QLabel* level_;
  QLabel* verdict_;
  QTableWidget* table_;
  QTableWidget* candidates_;
};

}  // namespace plumb::ui
