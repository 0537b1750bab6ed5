#include "ui/panels/point_style_editor.hpp"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QStandardItemModel>

#include "ui/layers/dataset_layer.hpp"
#include "ui/layers/scene.hpp"
#include "ui/panels/focus_wheel.hpp"

namespace plumb::ui {

PointStyleEditor::PointStyleEditor(Scene& scene, QWidget* parent)
    : QWidget(parent),
      scene_(scene),
      // The wheel over the Properties dock scrolls past these unless the user clicked in.
      mode_(new FocusWheel<QComboBox>(this)),
      field_(new FocusWheel<QComboBox>(this)),
      size_(new FocusWheel<QDoubleSpinBox>(this)),
      registered_(new QCheckBox(tr("Show registered position"), this)) {
  auto* form = new QFormLayout(this);
  form->setContentsMargins(0, 0, 0, 0);
  mode_->setObjectName("colorMode");
  for (const auto& name : pointColorModeNames()) mode_->addItem(QString::fromStdString(name));
  form->addRow(tr("Colour by"), mode_);
  field_->setObjectName("scalarField");
  form->addRow(tr("Scalar field"), field_);
  size_->setObjectName("pointSize");
  size_->setRange(1.0, 10.0);
  size_->setSingleStep(1.0);
  size_->setDecimals(0);
  size_->setSuffix(" px");
  form->addRow(tr("Point size"), size_);
  registered_->setObjectName("showRegistered");
  registered_->setToolTip(tr("Before/after: toggle the registration transform of this dataset"));
  form->addRow(registered_);
  connect(mode_, &QComboBox::currentIndexChanged, this, &PointStyleEditor::apply);
  connect(field_, &QComboBox::currentIndexChanged, this, &PointStyleEditor::apply);
  connect(size_, &QDoubleSpinBox::valueChanged, this, &PointStyleEditor::apply);
  connect(registered_, &QCheckBox::toggled, this, [this](bool on) {
    if (loading_ || !layer_) return;
    layer_->setShowsTransform(on);
    scene_.layerChanged(layer_);
  });
}

void PointStyleEditor::setLayer(DatasetLayer* layer) {
  layer_ = layer;
  if (!layer_) return;
  loading_ = true;
  const PointStyle& s = layer_->style();
  enableModes();
  mode_->setCurrentIndex(static_cast<int>(s.mode));
  field_->clear();
  for (const auto& name : layer_->scalarFieldNames()) field_->addItem(QString::fromStdString(name));
  field_->setCurrentText(QString::fromStdString(s.scalar_field));
  field_->setEnabled(field_->count() > 0);
  size_->setValue(s.point_size);
  registered_->setEnabled(!layer_->transform().isIdentity());
  registered_->setChecked(layer_->showsTransform());
  loading_ = false;
}

void PointStyleEditor::enableModes() {
  // Modes the data cannot show are greyed out with the reason, instead of silently drawing
  // elevation in their place.
  auto* model = qobject_cast<QStandardItemModel*>(mode_->model());
  auto set = [&](PointColorMode mode, bool available, const QString& why) {
    QStandardItem* item = model->item(static_cast<int>(mode));
    item->setEnabled(available);
    item->setToolTip(available ? QString() : why);
  };
  set(PointColorMode::Rgb, layer_->hasColors(), tr("This file has no RGB colours"));
  set(PointColorMode::Intensity, layer_->hasIntensity(), tr("This file has no intensities"));
  set(PointColorMode::ScalarField, !layer_->scalarFieldNames().empty(), tr("This file has no scalar fields"));
  set(PointColorMode::Distance, layer_->hasDistances(), tr("Register this dataset first: distances to the target"));
}

void PointStyleEditor::apply() {
  if (loading_ || !layer_) return;
  PointStyle s;
  s.mode = static_cast<PointColorMode>(mode_->currentIndex());
  s.scalar_field = field_->currentText().toStdString();
  s.point_size = size_->value();
  // Point size at once; colours computed in a background task (the old ones stay meanwhile).
  scene_.requestStyle(*layer_, s);
  emit styleApplied();
}

}  // namespace plumb::ui
