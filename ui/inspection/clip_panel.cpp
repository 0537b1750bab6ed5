#include "ui/inspection/clip_panel.hpp"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

#include "ui/app_context.hpp"
#include "ui/layers/dataset_layer.hpp"
#include "ui/layers/layer_transform.hpp"
#include "ui/layers/scene.hpp"
#include "ui/panels/focus_wheel.hpp"
#include "ui/view/scene_framing.hpp"

namespace plumb::ui {

namespace {
constexpr const char* kAxes[] = {"X", "Y", "Z"};

/// Axes a mode bounds.
std::array<bool, 3> boundedAxes(ClipPanel::Mode m) {
  switch (m) {
    case ClipPanel::Mode::PlanSlice: return {false, false, true};
    case ClipPanel::Mode::SectionX: return {true, false, false};
    case ClipPanel::Mode::SectionY: return {false, true, false};
    case ClipPanel::Mode::Box: return {true, true, true};
    case ClipPanel::Mode::Off: break;
  }
  return {false, false, false};
}

QDoubleSpinBox* metresBox(QWidget* parent, double min) {
  auto* b = new FocusWheel<QDoubleSpinBox>(parent);
  b->setRange(min, 1e8);
  b->setDecimals(3);
  b->setSingleStep(0.05);
  b->setSuffix(" m");
  return b;
}
}  // namespace

ClipPanel::ClipPanel(AppContext& app, QWidget* parent)
    : QWidget(parent), app_(app), mode_(new FocusWheel<QComboBox>(this)), count_(new QLabel(this)) {
  setObjectName("clipPanel");
  auto* layout = new QVBoxLayout(this);
  mode_->setObjectName("clipMode");
  mode_->addItems({tr("Off"), tr("Plan slice (height)"), tr("Section across X"), tr("Section across Y"), tr("Box")});
  layout->addWidget(mode_);
  auto* form = new QFormLayout;
  for (int a = 0; a < 3; ++a) {
    centre_[a] = metresBox(this, -1e8);
    size_[a] = metresBox(this, 0.001);
    centre_[a]->setObjectName(QString("clipCentre%1").arg(kAxes[a]));
    size_[a]->setObjectName(QString("clipSize%1").arg(kAxes[a]));
    size_[a]->setValue(0.1);
    auto* row = new QHBoxLayout;
    row->addWidget(centre_[a], 2);
    row->addWidget(new QLabel(tr("size"), this));
    row->addWidget(size_[a], 1);
    form->addRow(tr("%1 centre").arg(kAxes[a]), row);
    connect(centre_[a], &QDoubleSpinBox::valueChanged, this, [this] { apply(); });
    connect(size_[a], &QDoubleSpinBox::valueChanged, this, [this] { apply(); });
  }
  layout->addLayout(form);
  auto* fit = new QPushButton(tr("Fit to data"), this);
  fit->setObjectName("clipFit");
  layout->addWidget(fit);
  count_->setObjectName("clipCount");
  layout->addWidget(count_);
  layout->addStretch(1);
  connect(mode_, &QComboBox::currentIndexChanged, this, [this] {
    apply();
    lookAtSlice();
  });
  connect(fit, &QPushButton::clicked, this, &ClipPanel::fitToData);
  apply();
}

void ClipPanel::setAxis(int axis, double centre, double size) {
  updating_ = true;
  centre_[axis]->setValue(centre);
  size_[axis]->setValue(size);
  updating_ = false;
  apply();
}

void ClipPanel::fitToData() {
  const Bounds b = app_.scene.visibleFramingBounds();
  if (b.empty()) return;
  const bool box = mode_->currentIndex() == static_cast<int>(Mode::Box);
  updating_ = true;
  for (int a = 0; a < 3; ++a) {
    centre_[a]->setValue(b.center()[a]);
    size_[a]->setValue(box ? b.size()[a] : 0.1);
  }
  updating_ = false;
  apply();
}

std::optional<ClipBox> ClipPanel::box() const {
  const auto bounded = boundedAxes(static_cast<Mode>(mode_->currentIndex()));
  if (!bounded[0] && !bounded[1] && !bounded[2]) return std::nullopt;
  ClipBox box;
  for (int a = 0; a < 3; ++a) {
    if (!bounded[a]) continue;
    box.min[a] = centre_[a]->value() - size_[a]->value() / 2;
    box.max[a] = centre_[a]->value() + size_[a]->value() / 2;
  }
  return box;
}

void ClipPanel::lookAtSlice() {
  switch (static_cast<Mode>(mode_->currentIndex())) {
    case Mode::PlanSlice: frameScene(app_.scene, app_.view, StandardView::Top); break;
    case Mode::SectionX: frameScene(app_.scene, app_.view, StandardView::Right); break;
    case Mode::SectionY: frameScene(app_.scene, app_.view, StandardView::Front); break;
    case Mode::Off:
    case Mode::Box: break;  // the camera stays where the user put it
  }
}

void ClipPanel::apply() {
  if (updating_) return;
  const auto b = box();
  const auto bounded = boundedAxes(static_cast<Mode>(mode_->currentIndex()));
  for (int a = 0; a < 3; ++a) centre_[a]->setEnabled(bounded[a]), size_[a]->setEnabled(bounded[a]);
  app_.scene.setClipBox(b);
  inside_ = 0;
  if (b) {
    for (const auto& l : app_.scene.layers())
      if (l->kind() == LayerKind::Dataset && l->effectivelyVisible())
        inside_ += countInside(static_cast<const DatasetLayer&>(*l).dataset(), *b, layerTransform(*l));
  }
  count_->setText(b ? tr("%1 points inside").arg(inside_) : tr("No clipping"));
}

}  // namespace plumb::ui
