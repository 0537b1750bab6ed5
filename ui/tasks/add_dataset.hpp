#pragma once
// Adding a dataset that is already in memory (e.g. simulated or computed) without blocking the
// UI thread: its display data (random point order, colours) is prepared in a background task,
// the layer (VTK objects wrapping that data) is made on the UI thread when it is ready.
#include <functional>
#include <memory>

#include "model/dataset.hpp"

namespace plumb::ui {

class DatasetLayer;
class Scene;
class Task;
class TaskManager;

/// Called on the UI thread with the new layer.
using OnDatasetAdded = std::function<void(DatasetLayer& layer)>;

/// Starts the task; `added` runs after the layer was added to `scene` (not when cancelled).
/// `scene` must outlive the task.
Task* addDatasetInBackground(TaskManager& tasks, Scene& scene, std::shared_ptr<const Dataset> data,
                             OnDatasetAdded added = {});

}  // namespace plumb::ui
