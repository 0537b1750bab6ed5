#pragma once
// The registration workflow's background work, on the same core calls as plumb-cli register
// (makeRegistrationInput + extractFeatures / registerData, computeDistances): each function
// starts a Task that copies what it needs from the layers, runs off the UI thread, and hands
// its result back on the UI thread. The task holds its layers (TaskManager::holds) and checks
// they still exist before touching them: when one was destroyed meanwhile, the result is
// dropped and the task finishes with an error saying so.
#include <QString>

#include <functional>
#include <memory>

#include "quality/cloud_distance.hpp"
#include "model/rigid_transform.hpp"
#include "registration/auto/registration_input.hpp"
#include "registration/auto/registration_pipeline.hpp"

namespace plumb::ui {

struct AppContext;
class DatasetLayer;
class Layer;
class Task;

/// What a layer holds, shared with a worker (the layer itself stays on the UI thread).
struct LayerData {
  std::shared_ptr<const Dataset> dataset;
  std::shared_ptr<const BimModel> model;
  RigidTransform to_world;
  std::shared_ptr<const FeatureSet> features;  ///< detected overlay, data frame
  QString name;
  ModelElementFilter elements;  ///< a model's chosen elements (issue 14); empty: all
};
/// InputError when the layer is neither a dataset nor a model.
LayerData dataOf(const Layer& layer);
/// The registration input of the layer's data placed by `to_world` (on a worker thread); a
/// model keeps only `data.elements` (InputError when that keeps nothing).
RegistrationInput inputOf(const LayerData& data, const RigidTransform& to_world);

/// Features of each layer in its own data frame (a scan: planes, openings, segments; a model:
/// sharp edges), shown as overlays under the layers (replacing earlier ones).
Task* startFeatureDetection(AppContext& app, Layer& source, Layer& target,
                            const PipelineParams& params, std::function<void()> done = {},
                            const ModelElementFilter& target_elements = {});

/// registerData(source, target) with both sides in world coordinates (their current
/// transforms). `use_features`: the layers' detected overlays replace extraction. The result's
/// transform maps the source's world position at the start (`start`) to its registered one;
/// `done` gets the source the task started with.
using RegistrationDone = std::function<void(std::shared_ptr<const PipelineResult> result,
                                            Layer& source, const RigidTransform& start)>;
Task* startRegistration(AppContext& app, Layer& source, Layer& target, const PipelineParams& params,
                        bool use_features, RegistrationDone done,
                        const ModelElementFilter& target_elements = {});

/// Per-scan distances of a dataset layer to the target (cloud-to-cloud for a dataset,
/// cloud-to-mesh for a model), as shown (current transforms), with the target they were
/// measured to (in world) and how: the source's full-resolution detail is coloured the same way.
struct LayerDistances : DatasetDistances {
  std::shared_ptr<const RegistrationInput> target;
  DistanceParams params;
};
using DistancesDone = std::function<void(std::shared_ptr<const LayerDistances> distances,
                                         DatasetLayer& source, Layer& target)>;
Task* startDistanceComputation(AppContext& app, Layer& source, Layer& target,
                               const DistanceParams& params, DistancesDone done);

/// The overlay child of a layer holding detected features, or nullptr.
Layer* featureOverlay(const Layer& layer);

}  // namespace plumb::ui
