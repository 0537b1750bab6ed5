#include "ui/network/reference_combo.hpp"

#include <algorithm>

#include "ui/layers/scene.hpp"
#include "ui/network/network_tasks.hpp"

namespace plumb::ui {

namespace {
// Item data: a station by its name (QString), a model layer by its address (quintptr, only
// compared with the scene's layers, never dereferenced), the first station by 0.
QVariant modelData(const Layer* layer) { return QVariant::fromValue(quintptr(layer)); }
}  // namespace

ReferenceCombo::ReferenceCombo(QWidget* parent) : QComboBox(parent) {
  setObjectName("networkReference");
  setToolTip(tr("The station that keeps its pose (when no control points georeference the network); with a "
                "model, every station is also registered onto it and the network comes out in the model's frame"));
  setSizeAdjustPolicy(QComboBox::AdjustToContents);
}

void ReferenceCombo::refresh(const Scene& scene) {
  const QVariant chosen = currentData();
  clear();
  addItem(tr("first station"), modelData(nullptr));
  for (const std::string& name : sceneInputs(scene, nullptr).stationNames())
    addItem(tr("station %1").arg(QString::fromStdString(name)), QString::fromStdString(name));
  for (const auto& layer : scene.layers())
    if (layer->kind() == LayerKind::Model) addItem(tr("model: %1").arg(layer->name()), modelData(layer.get()));
  setCurrentIndex(std::max(0, findData(chosen)));
}

const Layer* ReferenceCombo::model(const Scene& scene) const {
  const QVariant data = currentData();
  if (data.typeId() == QMetaType::QString || data.value<quintptr>() == 0) return nullptr;  // a station
  for (const auto& layer : scene.layers())
    if (quintptr(layer.get()) == data.value<quintptr>()) return layer.get();
  return nullptr;  // the layer is gone: refresh() had not run yet
}

std::string ReferenceCombo::station() const {
  const QVariant data = currentData();
  return data.typeId() == QMetaType::QString ? data.toString().toStdString() : std::string();
}

bool ReferenceCombo::chooseStation(const QString& name) {
  const int i = findData(name);
  if (i >= 0) setCurrentIndex(i);
  return i >= 0;
}

}  // namespace plumb::ui
