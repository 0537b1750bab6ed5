#pragma once
// Exports in the background: a registered dataset (PLY, E57 with the registered scan poses,
// LAS; format by extension through plumb::writeDataset, like plumb-cli register -o), with the
// distances it is coloured by as the scalar field "distance" (like register --distances), and
// a layer's transform (JSON or 4x4 text through plumb::writeTransformFile).
#include <QString>

namespace plumb::ui {

struct AppContext;
class Layer;
class Task;

/// The dataset with its registration applied to every scan pose. InputError for a model.
/// A layer opened as a subsample (DatasetLayer::subsampledFrom) exports its whole file,
/// streamed through the transform (convertPointFile), without the subsample's distances.
Task* exportRegisteredDataset(AppContext& app, const Layer& layer, const QString& path);
/// The layer's transform (data frame -> world).
Task* exportTransform(AppContext& app, const Layer& layer, const QString& path);

}  // namespace plumb::ui
