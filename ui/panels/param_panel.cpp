#include "ui/panels/param_panel.hpp"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

#include <climits>
#include <cmath>

#include "ui/panels/focus_wheel.hpp"

namespace plumb::ui {

namespace {

/// Decimals showing the range's precision (at least 2, at most 6).
int decimalsFor(const ParamSpec& s) {
  const double span = std::max(std::abs(s.min), std::abs(s.max));
  const double smallest = std::min(std::abs(s.min) > 0 ? std::abs(s.min) : span, span);
  if (smallest <= 0) return 3;
  return std::clamp(static_cast<int>(std::ceil(-std::log10(smallest))) + 2, 2, 6);
}

}  // namespace

ParamPanel::ParamPanel(std::vector<ParamSpec> specs, Getter get, Setter set, QWidget* parent)
    : QWidget(parent), specs_(std::move(specs)), get_(std::move(get)), set_(std::move(set)) {
  auto* layout = new QVBoxLayout(this);
  auto* basic = new QFormLayout;
  layout->addLayout(basic);
  auto* advanced_box = new QGroupBox(tr("Advanced"), this);
  advanced_box->setCheckable(true);
  advanced_box->setChecked(false);
  auto* advanced = new QFormLayout(advanced_box);
  auto* advanced_content = new QWidget(advanced_box);
  advanced->addRow(advanced_content);
  auto* advanced_form = new QFormLayout(advanced_content);
  advanced_content->setVisible(false);
  connect(advanced_box, &QGroupBox::toggled, advanced_content, &QWidget::setVisible);
  bool any_advanced = false;
  for (std::size_t i = 0; i < specs_.size(); ++i) {
    QWidget* e = makeEditor(i);
    editors_.push_back(e);
    const ParamSpec& s = specs_[i];
    e->setObjectName(QString::fromStdString(s.key));
    e->setToolTip(QString::fromStdString(s.help));
    auto* label = new QLabel(QString::fromStdString(s.label), this);
    label->setToolTip(QString::fromStdString(s.help));
    labels_.push_back(label);
    (s.advanced ? advanced_form : basic)->addRow(label, e);
    any_advanced |= s.advanced;
  }
  if (any_advanced) layout->addWidget(advanced_box);
  else advanced_box->hide();
  reset_ = new QPushButton(tr("Reset to defaults"), this);
  reset_->setObjectName("resetToDefaults");
  reset_->setToolTip(tr("Sets every parameter of this group back to its default"));
  reset_->hide();  // until defaults are known
  connect(reset_, &QPushButton::clicked, this, &ParamPanel::resetToDefaults);
  layout->addWidget(reset_, 0, Qt::AlignLeft);
  layout->addStretch(1);
  refresh();
}

void ParamPanel::setDefaults(std::vector<double> defaults) {
  defaults_ = std::move(defaults);
  defaults_.resize(specs_.size(), 0.0);
  reset_->show();
  markModified();
}

bool ParamPanel::modified(std::size_t i) const {
  if (i >= defaults_.size()) return false;
  const double v = get_(i), d = defaults_[i];
  return std::abs(v - d) > 1e-9 * std::max(1.0, std::abs(d));
}

bool ParamPanel::isModified(const std::string& key) const {
  for (std::size_t i = 0; i < specs_.size(); ++i)
    if (specs_[i].key == key) return modified(i);
  return false;
}

void ParamPanel::markModified() {
  bool any = false;
  for (std::size_t i = 0; i < specs_.size(); ++i) {
    const bool m = modified(i);
    any |= m;
    QFont f = labels_[i]->font();
    f.setBold(m);
    labels_[i]->setFont(f);
    QString tip = QString::fromStdString(specs_[i].help);
    if (m)
      tip = tr("Changed (default %1). %2")
                .arg(QString::fromStdString(formatParamValue(specs_[i], defaults_[i])), tip);
    labels_[i]->setToolTip(tip);
  }
  reset_->setEnabled(any);
}

void ParamPanel::resetToDefaults() {
  for (std::size_t i = 0; i < defaults_.size(); ++i) set_(i, defaults_[i]);
  refresh();
  emit changed();
}

QWidget* ParamPanel::makeEditor(std::size_t i) {
  const ParamSpec& s = specs_[i];
  auto commit = [this, i](double v) {
    if (loading_) return;
    set_(i, v);
    markModified();
    emit changed();
  };
  const QString unit = s.unit.empty() ? QString() : " " + QString::fromStdString(s.unit);
  switch (s.kind) {
    case ParamKind::Real: {
      auto* e = new FocusWheel<QDoubleSpinBox>(this);
      e->setDecimals(decimalsFor(s));
      e->setRange(s.min, s.max);
      e->setSingleStep((s.max - s.min) / 100.0);
      e->setSuffix(unit);
      connect(e, &QDoubleSpinBox::valueChanged, this, commit);
      return e;
    }
    case ParamKind::Integer: {
      auto* e = new FocusWheel<QSpinBox>(this);
      e->setRange(static_cast<int>(std::max<double>(s.min, INT_MIN)),
                  static_cast<int>(std::min<double>(s.max, INT_MAX)));
      e->setSuffix(unit);
      connect(e, &QSpinBox::valueChanged, this, [commit](int v) { commit(v); });
      return e;
    }
    case ParamKind::Boolean: {
      auto* e = new QCheckBox(this);
      connect(e, &QCheckBox::toggled, this, [commit](bool on) { commit(on ? 1.0 : 0.0); });
      return e;
    }
    case ParamKind::Choice: break;
  }
  auto* e = new FocusWheel<QComboBox>(this);
  for (const auto& c : s.choices) e->addItem(QString::fromStdString(c));
  connect(e, &QComboBox::currentIndexChanged, this, [commit](int v) { commit(v); });
  return e;
}

void ParamPanel::refresh() {
  loading_ = true;
  for (std::size_t i = 0; i < specs_.size(); ++i) {
    const double v = get_(i);
    if (auto* d = qobject_cast<QDoubleSpinBox*>(editors_[i])) d->setValue(v);
    else if (auto* n = qobject_cast<QSpinBox*>(editors_[i])) n->setValue(static_cast<int>(v));
    else if (auto* b = qobject_cast<QCheckBox*>(editors_[i])) b->setChecked(v != 0.0);
    else if (auto* c = qobject_cast<QComboBox*>(editors_[i])) c->setCurrentIndex(static_cast<int>(v));
  }
  loading_ = false;
  markModified();
}

QWidget* ParamPanel::editor(const std::string& key) const {
  for (std::size_t i = 0; i < specs_.size(); ++i)
    if (specs_[i].key == key) return editors_[i];
  return nullptr;
}

}  // namespace plumb::ui
