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
/// (world); the layer's bounds for other layers.
Bounds bulkBounds(const Layer& layer) {
  if (layer.kind() != LayerKind::Dataset) return layer.bounds();
  std::vector<Eigen::Vector3d> samples;
  for (const ScanLayer* scan : static_cast<const DatasetLayer&>(layer).scans()) {
    const auto& pts = scan->scan().cloud.positions;
    const Eigen::Matrix4d m = scan->localToWorld();
    const std::size_t step = std::max<std::size_t>(1, pts.size() / 20000);
    for (std::size_t i = 0; i < pts.size(); i += step)
      samples.push_back((m * pts[i].cast<double>().homogeneous()).head<3>());
  }
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
