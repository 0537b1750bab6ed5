#include "ui/registration/registration_result_box.hpp"

#include <QCheckBox>
#include <QHBoxLayout>
#include <QPushButton>
#include <QVBoxLayout>

#include "ui/registration/applied_registration.hpp"
#include "ui/registration/quality_report_view.hpp"
#include "ui/registration/registration_runner.hpp"

namespace plumb::ui {

namespace {
void uncheckQuietly(QCheckBox& box) {
  box.blockSignals(true);
  box.setChecked(false);
  box.blockSignals(false);
}
}  // namespace

RegistrationResultBox::RegistrationResultBox(RegistrationRunner& runner, QWidget* parent)
    : QGroupBox(tr("Result"), parent),
      runner_(runner),
      report_(new QualityReportView(this)),
      before_(new QCheckBox(tr("Show before registration"), this)),
      accept_(new QPushButton(tr("Accept"), this)),
      revert_(new QPushButton(tr("Revert"), this)) {
  before_->setObjectName("showBefore");
  accept_->setObjectName("acceptResult");
  revert_->setObjectName("revertResult");
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(report_, 1);
  layout->addWidget(before_);
  auto* keep = new QHBoxLayout;
  keep->addWidget(accept_);
  keep->addWidget(revert_);
  layout->addLayout(keep);

  connect(accept_, &QPushButton::clicked, this, &RegistrationResultBox::accept);
  connect(revert_, &QPushButton::clicked, this, &RegistrationResultBox::revert);
  connect(before_, &QCheckBox::toggled, this, &RegistrationResultBox::showBefore);
  connect(&runner_, &RegistrationRunner::newResult, this, &RegistrationResultBox::showResult);
  connect(&runner_, &RegistrationRunner::resultWithdrawn, report_, [this] { report_->clear(); });
  connect(&runner_.applied(), &AppliedRegistration::changed, this,
          &RegistrationResultBox::followAppliedResult);
  followAppliedResult();
}

void RegistrationResultBox::accept() { runner_.applied().accept(); }

void RegistrationResultBox::revert() {
  if (!runner_.applied().undecided()) return;
  before_->setChecked(false);
  runner_.applied().revert();
}

void RegistrationResultBox::showBefore(bool before) {
  if (before_->isChecked() != before) {
    before_->setChecked(before);  // re-enters through toggled
    return;
  }
  runner_.applied().showBefore(before);
}

void RegistrationResultBox::showResult(const PipelineResult& result) {
  report_->showResult(result);
  uncheckQuietly(*before_);
}

void RegistrationResultBox::followAppliedResult() {
  // Undone (Edit > Undo, Revert) or redone: the report describes the result only while it is
  // in effect.
  const AppliedRegistration& applied = runner_.applied();
  const auto result = runner_.lastResult();
  if (!applied.inEffect()) {
    uncheckQuietly(*before_);
    if (result && result->success()) {
      report_->clear(tr("<i>The registration of %1 was undone.</i>")
                         .arg(applied.layer() ? applied.layer()->name() : QString()));
      emit undone(applied.layer());
    }
  } else if (result && report_->level().isEmpty()) {
    report_->showResult(*result);  // redone
  }
  accept_->setEnabled(applied.undecided());
  revert_->setEnabled(applied.undecided());
  before_->setEnabled(applied.inEffect());
}

}  // namespace plumb::ui
