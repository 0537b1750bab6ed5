#include "ui/layers/layer_transform.hpp"

#include "model/robust_bounds.hpp"

#include <QFileInfo>

#include <algorithm>
#include <array>

#include "ui/layers/dataset_layer.hpp"
#include "ui/layers/model_layer.hpp"
#include "ui/layers/scan_layer.hpp"
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

/// The 3%..97% quantiles per axis (robustBounds, no margin) of a sample of a dataset's points
/// (world, about 20000 per scan); the layer's bounds for other layers.
Bounds bulkBounds(const Layer& layer) {
  if (layer.kind() != LayerKind::Dataset) return layer.bounds();
  const auto& d = static_cast<const DatasetLayer&>(layer);
  std::vector<Eigen::Vector3d> samples = datasetSamples(d.dataset(), 20000 * d.dataset().scans.size());
  const RigidTransform shown = d.shownTransform();
  for (auto& p : samples) p = shown.apply(p);
  const Bounds b = robustBounds(std::move(samples), 0.03, 0.0);
  return b.empty() ? layer.bounds() : b;
}

Layer* findLayerBySource(const Scene& scene, const QString& path) {
  const QString wanted = QFileInfo(path).absoluteFilePath();
  for (const auto& l : scene.layers())
    if (isRegistrable(l.get()) && QFileInfo(layerSource(*l)).absoluteFilePath() == wanted)
      return l.get();
  return nullptr;
}

}  // namespace plumb::ui
