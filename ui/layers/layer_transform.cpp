#include "ui/layers/layer_transform.hpp"

#include <QFileInfo>

#include "ui/layers/dataset_layer.hpp"
#include "ui/layers/model_layer.hpp"
#include "ui/layers/scene.hpp"

namespace plumb::ui {

bool isRegistrable(const Layer* layer) {
  return layer && (layer->kind() == LayerKind::Dataset || layer->kind() == LayerKind::Model);
}

RigidTransform layerTransform(const Layer& layer) {
  if (layer.kind() == LayerKind::Dataset) return static_cast<const DatasetLayer&>(layer).transform();
  if (layer.kind() == LayerKind::Model) return static_cast<const ModelLayer&>(layer).transform();
  return {};
}

void setLayerTransform(Scene& scene, Layer& layer, const RigidTransform& t) {
  if (layer.kind() == LayerKind::Dataset) static_cast<DatasetLayer&>(layer).setTransform(t);
  else if (layer.kind() == LayerKind::Model) static_cast<ModelLayer&>(layer).setTransform(t);
  else return;
  scene.layerChanged(&layer);
}

QString layerSource(const Layer& layer) {
  std::filesystem::path p;
  if (layer.kind() == LayerKind::Dataset) p = static_cast<const DatasetLayer&>(layer).dataset().source;
  if (layer.kind() == LayerKind::Model) p = static_cast<const ModelLayer&>(layer).model().source;
  return QString::fromStdString(p.string());
}

Layer* findLayerBySource(const Scene& scene, const QString& path) {
  const QString wanted = QFileInfo(path).absoluteFilePath();
  for (const auto& l : scene.layers())
    if (isRegistrable(l.get()) && QFileInfo(layerSource(*l)).absoluteFilePath() == wanted)
      return l.get();
  return nullptr;
}

}  // namespace plumb::ui
