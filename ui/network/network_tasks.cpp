#include "ui/network/network_tasks.hpp"

#include <algorithm>

#include "common/error.hpp"
#include "ui/app_context.hpp"
#include "ui/layers/dataset_layer.hpp"
#include "ui/layers/layer_transform.hpp"
#include "ui/layers/model_layer.hpp"
#include "ui/layers/scan_layer.hpp"
#include "ui/layers/scene.hpp"
#include "ui/tasks/task_manager.hpp"

namespace plumb::ui {

namespace {

std::string fileOf(const Layer& layer) {
  const QString source = layerSource(layer);
  return (source.isEmpty() ? layer.name() : source).toStdString();
}

NetworkInputs::Source datasetSource(DatasetLayer& layer) {
  NetworkInputs::Source s{layer.sharedDataset(), fileOf(layer), LayerRef(layer), {}, 0.0};
  for (const ScanLayer* scan : layer.scans()) s.colour_indices.push_back(scan->colourIndex());
  if (layer.subsampledFrom()) s.subsample_voxel = layer.subsampledFrom()->voxel;
  return s;
}

/// The stations as plumb-cli network builds them.
std::vector<Station> buildStations(const NetworkInputs& in) {
  std::vector<StationFile> files;
  for (const auto& d : in.datasets) files.push_back({d.data.get(), d.file, d.subsample_voxel});
  std::vector<Station> stations = stationsOfFiles(files);
  if (in.model) stations.push_back(modelStation(*in.model, in.model_file));  // last: the reference
  return stations;
}

}  // namespace

std::size_t NetworkInputs::stationCount() const {
  std::size_t n = model ? 1 : 0;
  for (const auto& d : datasets) n += d.data->scans.size();
  return n;
}

std::vector<std::string> NetworkInputs::stationNames() const {
  std::vector<Station> named;  // names and files only: what makeStationNamesUnique reads
  for (const auto& d : datasets)
    for (std::size_t i = 0; i < d.data->scans.size(); ++i) {
      Station s;
      s.name = stationName(d.data->scans[i], i);  // as stationsOf
      s.file = d.file;
      named.push_back(std::move(s));
    }
  makeStationNamesUnique(named);
  return plumb::stationNames(named);
}

std::size_t NetworkInputs::referenceIndex() const {
  if (model && !reference_station.empty())
    throw InputError("a model and a reference station exclude each other (with a model, the model is the reference)");
  if (model) return stationCount() - 1;
  if (reference_station.empty()) return 0;
  const auto names = stationNames();
  const auto it = std::find(names.begin(), names.end(), reference_station);
  if (it == names.end()) {
    std::string list;
    for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
    throw InputError("no station is named '" + reference_station + "'; the stations are: " + list);
  }
  return std::size_t(it - names.begin());
}

std::vector<LayerRef> NetworkInputs::layers() const {
  std::vector<LayerRef> out;
  for (const auto& d : datasets) out.push_back(d.layer);
  if (model) out.push_back(model_layer);
  return out;
}

std::vector<StationSource> NetworkInputs::sources() const {
  std::vector<StationSource> out;
  for (const auto& d : datasets)
    for (std::size_t k = 0; k < d.data->scans.size(); ++k)
      out.push_back({d.layer, k, false, k < d.colour_indices.size() ? d.colour_indices[k] : k});
  if (model) out.push_back({model_layer, 0, true, 0});
  return out;
}

NetworkInputs sceneInputs(const Scene& scene, const Layer* model) {
  NetworkInputs in;
  for (const auto& layer : scene.layers()) {
    if (layer->kind() == LayerKind::Dataset) in.datasets.push_back(datasetSource(static_cast<DatasetLayer&>(*layer)));
    if (layer.get() == model && model->kind() == LayerKind::Model) {
      auto& m = static_cast<ModelLayer&>(*layer);
      in.model = m.sharedModel();
      in.model_file = fileOf(m);
      in.model_layer = LayerRef(m);
    }
  }
  return in;
}

NetworkInputs networkInputs(const Scene& scene, const Layer* model) {
  NetworkInputs in = sceneInputs(scene, model);
  if (in.stationCount() < 2)
    throw InputError("a network needs at least two stations: open the scans (every scan of every point dataset is "
                     "a station), or one scan and a model as the reference");
  return in;
}

Task* startNetworkRegistration(AppContext& app, NetworkInputs inputs, const NetworkParams& params,
                               NetworkDone done) {
  const std::vector<LayerRef> holds = inputs.layers();
  return app.tasks.run(QObject::tr("Registering the network"), [inputs = std::move(inputs), params,
                                                                  done](Progress& progress) {
    if (params.mms.window > 0)  // the desktop maps one station to one scan of a layer
      throw InputError("MMS passes cut into time windows (mms.window) are registered by plumb-cli network; the "
                       "desktop registers a pass as one node: set mms.window to 0");
    auto stations = std::make_shared<std::vector<Station>>(buildStations(inputs));
    Progress features = progress.sub(0.0, 0.3);
    detectStationsFeatures(*stations, params.link, features);
    Progress linking = progress.sub(0.3, 1.0);
    auto result = std::make_shared<const NetworkResult>(
        registerNetwork(*stations, inputs.referenceIndex(), params, &linking, inputs.control.get()));
    auto session = std::make_shared<NetworkSession>();
    session->control = inputs.control;  // the re-runs georeference on the same survey
    session->stations = std::move(stations);
    session->sources = inputs.sources();
    session->params = params;
    session->registered = result;
    session->setResult(std::move(result));  // the report is built here, off the UI thread
    return [session, done] { done(session); };
  }, holds);
}

Task* startNetworkAdjustment(AppContext& app, const NetworkSession& session, const NetworkDecisions& decisions,
                             AdjustmentDone done) {
  std::vector<LayerRef> holds;
  for (const auto& s : session.sources) holds.push_back(s.layer);
  return app.tasks.run(QObject::tr("Adjusting the network"),
                       [stations = session.stations, registered = session.registered, params = session.params,
                        control = session.control, decisions, done](Progress& progress) {
    progress.report(0.0, "adjustment");
    auto adjusted = std::make_shared<const NetworkResult>(
        readjustNetwork(*stations, *registered, params, control.get(), decisions));
    return [adjusted, done] { done(adjusted); };
  }, holds);
}

}  // namespace plumb::ui
