#include "ui/registration/layer_pair_combos.hpp"

#include <QComboBox>

#include "ui/layers/layer_transform.hpp"
#include "ui/layers/scene.hpp"
#include "ui/panels/focus_wheel.hpp"
#include "ui/registration/default_layers.hpp"

namespace plumb::ui {

LayerPairCombos::LayerPairCombos(Scene& scene, QWidget* parent)
    : QObject(parent),
      scene_(scene),
      source_(new FocusWheel<QComboBox>(parent)),
      target_(new FocusWheel<QComboBox>(parent)) {
  source_->setObjectName("sourceLayer");
  target_->setObjectName("targetLayer");
  for (QComboBox* c : {source_, target_}) {
    connect(c, &QComboBox::currentIndexChanged, this, &LayerPairCombos::changed);
    connect(c, &QComboBox::activated, this, [this] { chosen_ = true; });
  }
  connect(&scene_, &Scene::layersChanged, this, &LayerPairCombos::rebuild);
  rebuild();
}

Layer* LayerPairCombos::selected(const QComboBox& combo) {
  return static_cast<Layer*>(combo.currentData().value<void*>());
}
void LayerPairCombos::select(QComboBox& combo, const Layer* layer) {
  combo.setCurrentIndex(combo.findData(QVariant::fromValue(const_cast<void*>(static_cast<const void*>(layer)))));
}

Layer* LayerPairCombos::sourceLayer() const { return selected(*source_); }
Layer* LayerPairCombos::targetLayer() const { return selected(*target_); }

void LayerPairCombos::setSourceLayer(const Layer* layer) {
  chosen_ = true;
  select(*source_, layer);
}
void LayerPairCombos::setTargetLayer(const Layer* layer) {
  chosen_ = true;
  select(*target_, layer);
}

void LayerPairCombos::setEnabled(bool enabled) {
  source_->setEnabled(enabled);
  target_->setEnabled(enabled);
}

void LayerPairCombos::rebuild() {
  Layer* s = sourceLayer();
  Layer* t = targetLayer();
  for (QComboBox* c : {source_, target_}) {
    c->blockSignals(true);
    c->clear();
    for (const auto& l : scene_.layers())
      if (isRegistrable(l.get()))
        c->addItem(l->name() + " (" + layerKindName(l->kind()) + ")",
                   QVariant::fromValue(static_cast<void*>(l.get())));
    c->blockSignals(false);
  }
  if (scene_.layers().empty()) chosen_ = false;
  // The user's choice while both are still there; until then (or after) the default pair.
  select(*source_, s);
  select(*target_, t);
  if (!chosen_ || !sourceLayer() || !targetLayer() || sourceLayer() == targetLayer()) {
    const LayerPair pair = defaultRegistrationPair(scene_.layers());
    select(*source_, pair.source);
    select(*target_, pair.target);
  }
  emit changed();
}

}  // namespace plumb::ui
