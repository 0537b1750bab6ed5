#include "ui/panels/mesh_style_editor.hpp"

#include <QCheckBox>
#include <QFormLayout>
#include <QSlider>

#include "ui/layers/model_layer.hpp"
#include "ui/layers/scene.hpp"
#include "ui/panels/focus_wheel.hpp"

namespace plumb::ui {

MeshStyleEditor::MeshStyleEditor(Scene& scene, QWidget* parent)
    : QWidget(parent),
      scene_(scene),
      edges_(new QCheckBox(tr("Show edges"), this)),
      opacity_(new FocusWheel<QSlider>(this)) {  // the wheel only once clicked in
  auto* form = new QFormLayout(this);
  form->setContentsMargins(0, 0, 0, 0);
  edges_->setObjectName("meshEdges");
  form->addRow(edges_);
  opacity_->setObjectName("meshOpacity");
  opacity_->setOrientation(Qt::Horizontal);
  opacity_->setRange(5, 100);
  opacity_->setToolTip(tr("Opacity (%)"));
  form->addRow(tr("Opacity"), opacity_);
  connect(edges_, &QCheckBox::toggled, this, &MeshStyleEditor::apply);
  connect(opacity_, &QSlider::valueChanged, this, &MeshStyleEditor::apply);
}

void MeshStyleEditor::setLayer(ModelLayer* layer) {
  layer_ = layer;
  if (!layer_) return;
  loading_ = true;
  edges_->setChecked(layer_->style().edges);
  opacity_->setValue(static_cast<int>(layer_->style().opacity * 100.0 + 0.5));
  loading_ = false;
}

void MeshStyleEditor::apply() {
  if (loading_ || !layer_) return;
  layer_->setStyle({edges_->isChecked(), opacity_->value() / 100.0});
  scene_.layerChanged(layer_);
}

}  // namespace plumb::ui
