#include "ui/network/station_poses_command.hpp"

#include <QObject>

#include <algorithm>

#include "ui/layers/dataset_layer.hpp"
#include "ui/layers/layer_transform.hpp"
#include "ui/layers/scene.hpp"

namespace plumb::ui {

StationPosesCommand::StationPosesCommand(Scene& scene, std::vector<LayerPoses> layers)
    : QUndoCommand(QObject::tr("Apply network poses")), scene_(scene), layers_(std::move(layers)) {}

void StationPosesCommand::undo() { apply(false); }
void StationPosesCommand::redo() { apply(true); }

void StationPosesCommand::apply(bool after) {
  for (const auto& l : layers_) {
    Layer* layer = l.layer.get();
    if (!layer) {
      setObsolete(true);
      continue;
    }
    static_cast<DatasetLayer&>(*layer).setScanPoses(after ? l.after : l.before);
    setLayerTransform(scene_, *layer, after ? l.transform_after : l.transform_before);
  }
}

std::vector<StationPosesCommand::LayerPoses> stationPoses(const NetworkSession& session) {
  const NetworkResult& r = *session.result;
  const Layer* reference = session.sources[r.reference].layer.get();
  if (!reference) return {};
  const RigidTransform registered_to_world = layerTransform(*reference);
  std::vector<StationPosesCommand::LayerPoses> out;
  for (std::size_t i = 0; i < session.sources.size(); ++i) {
    const StationSource& s = session.sources[i];
    auto* layer = static_cast<DatasetLayer*>(s.layer.get());
    if (s.model || !layer || !r.placed(i)) continue;
    auto entry = std::find_if(out.begin(), out.end(), [&](const auto& l) { return l.layer.is(layer); });
    if (entry == out.end()) {
      const auto poses = layer->scanPoses();
      out.push_back({s.layer, poses, poses, layer->transform(), registered_to_world});
      entry = out.end() - 1;
    }
    entry->after.at(s.scan) = *r.adjustment.poses[i];
  }
  return out;
}

}  // namespace plumb::ui
