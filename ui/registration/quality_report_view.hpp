#pragma once
// The quality report of the last registration: the verdict (coloured by success) above a
// table of its figures (method, RMS, overlap, features, free space, runner-up gap, weak
// directions...).
#include <QWidget>

class QLabel;
class QTableWidget;

namespace plumb {
struct PipelineResult;
struct VisibilitySummary;
}

namespace plumb::ui {

class QualityReportView : public QWidget {
  Q_OBJECT
 public:
  explicit QualityReportView(QWidget* parent = nullptr);
  void showResult(const PipelineResult& result);
  void clear();
  QString verdict() const;
  /// Figure rows (name, value), for tests.
  int rowCount() const;

 private:
  void addRow(const QString& name, const QString& value);
  /// Free-space evidence: each direction's contradiction ratio (or why there is none) and
  /// the expected overlap.
  void addVisibilityRows(const VisibilitySummary& visibility);
  QLabel* verdict_;
  QTableWidget* table_;
};

}  // namespace plumb::ui
