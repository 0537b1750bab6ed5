#pragma once
// The registration transform of a root layer (dataset or model), whatever its kind, and
// lookups the registration workflow and project files need.
#include <QString>

#include "model/point_cloud.hpp"
#include "model/rigid_transform.hpp"

namespace plumb::ui {

class Layer;
class Scene;

/// A dataset or a model (a root layer that can be registered and moved).
bool isRegistrable(const Layer* layer);
/// Its transform (data frame -> world); identity for other layers.
RigidTransform layerTransform(const Layer& layer);
/// Sets the transform of a dataset or model (its feature overlays follow) and re-renders.
void setLayerTransform(Scene& scene, Layer& layer, const RigidTransform& t);
/// The file a dataset or model layer was read from (empty if generated).
QString layerSource(const Layer& layer);
/// Where most of a layer is: per axis the 3%..97% quantiles of a sample of a dataset's points
/// (world; scans see far ground through windows), the plain bounds for other layers.
Bounds bulkBounds(const Layer& layer);
/// The root layer read from `path` (absolute path compared), or nullptr.
Layer* findLayerBySource(const Scene& scene, const QString& path);

}  // namespace plumb::ui
