#pragma once
// The Registration dock's "Result" group: the quality report of the last registration, the
// before/after toggle, Accept and Revert. It describes the result only while it is in effect:
// Undo (Edit > Undo, Revert) withdraws it, Redo brings it back, a new registration replaces it
// and removing its layer clears it.
#include <QGroupBox>

class QCheckBox;
class QPushButton;

namespace plumb {
struct PipelineResult;
}

namespace plumb::ui {

class Layer;
class QualityReportView;
class RegistrationRunner;

class RegistrationResultBox : public QGroupBox {
  Q_OBJECT
 public:
  RegistrationResultBox(RegistrationRunner& runner, QWidget* parent = nullptr);

  const QualityReportView& report() const { return *report_; }
  /// Keep the applied result / undo it.
  void accept();
  void revert();
  /// Before/after: show the source where it was before the last registration.
  void showBefore(bool before);

 signals:
  /// The result applied to `layer` was undone: what was measured on the layer since is stale.
  void undone(plumb::ui::Layer* layer);

 private:
  void showResult(const plumb::PipelineResult& result);
  void followAppliedResult();

  RegistrationRunner& runner_;
  QualityReportView* report_;
  QCheckBox* before_;
  QPushButton* accept_;
  QPushButton* revert_;
};

}  // namespace plumb::ui
