#pragma once
// The Network dock's background work, on the core calls plumb-cli network makes: one station
// per scan of every point dataset layer (stationsOf, makeStationNamesUnique), the model layer
// last as the reference when chosen (modelStation), detectStationFeatures for each, then
// registerNetwork; and the re-run of the adjustment with the surveyor's decisions
// (adjustRegisteredLinks). Each starts a Task holding its layers; the result is handed back on
// the UI thread.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "ui/network/network_session.hpp"

namespace plumb::ui {

struct AppContext;
class Scene;
class Task;

/// What a network run reads from the layers, shared with the worker.
struct NetworkInputs {
  struct Source {
    std::shared_ptr<const Dataset> data;
    std::string file;  ///< the layer's file (station names take its stem when they clash)
    LayerRef layer;
    std::vector<std::size_t> colour_indices;  ///< each scan's Scan colour
    double subsample_voxel = 0.0;  ///< the layer holds a voxel subsample of its file (memory budget)
  };
  std::vector<Source> datasets;
  std::shared_ptr<const BimModel> model;  ///< the reference, when chosen
  std::string model_file;
  LayerRef model_layer;
  std::string reference_station;  ///< the reference by name (--reference); empty: the first, or the model
  std::shared_ptr<const ControlSurvey> control;  ///< null: not georeferenced

  std::size_t stationCount() const;
  /// The scan stations' names as the run gives them (stationsOf, makeStationNamesUnique), without
  /// reading a point: for the reference combo and the targets file's check before the run.
  std::vector<std::string> stationNames() const;
  /// The reference's index in the run's stations: the model (last), the named station, or 0.
  /// Throws InputError for a name no station has (naming the stations) or a name with a model.
  std::size_t referenceIndex() const;
  std::vector<LayerRef> layers() const;
  /// Where each station comes from, in station order.
  std::vector<StationSource> sources() const;
};

/// Every point dataset layer of `scene`, in its order, and `model` (a model layer, or nullptr)
/// as the reference.
NetworkInputs sceneInputs(const Scene& scene, const Layer* model);
/// sceneInputs, refused (InputError) when that makes fewer than two stations.
NetworkInputs networkInputs(const Scene& scene, const Layer* model);

using NetworkDone = std::function<void(std::shared_ptr<NetworkSession> session)>;
Task* startNetworkRegistration(AppContext& app, NetworkInputs inputs, const NetworkParams& params,
                               NetworkDone done);

using AdjustmentDone = std::function<void(std::shared_ptr<const NetworkResult> result)>;
/// adjustRegisteredLinks of the session's links with `decisions` and its control survey (milliseconds, still off the
/// UI thread: a large network's covariance is not free).
Task* startNetworkAdjustment(AppContext& app, const NetworkSession& session, const NetworkDecisions& decisions,
                             AdjustmentDone done);

}  // namespace plumb::ui
