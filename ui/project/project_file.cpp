#include "ui/project/project_file.hpp"

#include <QDir>
#include <QFileInfo>
#include <QMainWindow>
#include <QUndoStack>

#include <nlohmann/json.hpp>

#include <fstream>
#include <memory>
#include <sstream>

#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "common/params_json.hpp"
#include "features/export/feature_export.hpp"
#include "quality/cloud_distance.hpp"
#include "registration/auto/pipeline_param_groups.hpp"
#include "ui/app_context.hpp"
#include "ui/layers/dataset_layer.hpp"
#include "ui/layers/feature_layer.hpp"
#include "ui/layers/layer_transform.hpp"
#include "ui/project/feature_sidecar.hpp"
#include "ui/project/layer_style_json.hpp"
#include "ui/tasks/attach_trajectory.hpp"
#include "ui/layers/scene.hpp"
#include "ui/panels/log_panel.hpp"
#include "ui/registration/registration_panel.hpp"
#include "ui/registration/registration_tasks.hpp"
#include "ui/tasks/load_files.hpp"
#include "ui/tasks/task_manager.hpp"

namespace plumb::ui {

using nlohmann::json;

bool looksLikeProject(const QString& path) {
  return path.endsWith(".plumb.json", Qt::CaseInsensitive) ||
         path.endsWith(".json", Qt::CaseInsensitive);
}

namespace {

/// How the project names `file`: relative to the project's folder when below it, else absolute.
std::string projectPath(const QDir& dir, const QString& file) {
  const QString rel = dir.relativeFilePath(file);
  return (rel.startsWith("..") ? QFileInfo(file).absoluteFilePath() : rel).toStdString();
}

}  // namespace

void showProjectInTitle(QMainWindow& window, const QString& path) {
  window.setWindowTitle(path.isEmpty() ? QStringLiteral("Plumb") : QFileInfo(path).fileName() + " - Plumb");
  window.setWindowFilePath(path);
}

namespace {

/// The project's entry for layer `l`, the `index`th: file, visibility, transform, trajectory,
/// style and (in the feature folder, listed in `feature_files`) its detected features.
json layerEntry(const Layer& l, std::size_t index, const QString& project, const QDir& dir,
                QStringList& feature_files) {
  json e;
  e["file"] = projectPath(dir, layerSource(l));
  e["visible"] = l.visible();
  e["transform"] = json::parse(transformToJson(layerTransform(l)));
  if (l.kind() == LayerKind::Dataset) {
    const QString& trajectory = static_cast<const DatasetLayer&>(l).trajectoryPath();
    if (!trajectory.isEmpty()) e["trajectory"] = projectPath(dir, trajectory);
  }
  e["style"] = styleToJson(l);
  if (const Layer* overlay = featureOverlay(l)) {
    const auto& features = static_cast<const FeatureLayer*>(overlay)->features();
    feature_files << writeLayerFeatures(project, index, features);
    e["features"] = projectPath(dir, feature_files.back());
  }
  return e;
}

}  // namespace

void saveProject(const AppContext& app, const QString& path) {
  const QDir dir = QFileInfo(path).absoluteDir();
  json layers = json::array();
  QStringList feature_files;
  int source = -1, target = -1;
  for (const auto& l : app.scene.layers()) {
    if (!isRegistrable(l.get())) continue;
    if (layerSource(*l).isEmpty()) continue;  // generated data has no file to reopen
    if (app.registration && l.get() == app.registration->sourceLayer()) source = int(layers.size());
    if (app.registration && l.get() == app.registration->targetLayer()) target = int(layers.size());
    layers.push_back(layerEntry(*l, layers.size(), path, dir, feature_files));
  }
  removeStaleFeatureFiles(path, feature_files);
  json j;
  j["plumb-project"] = kProjectVersion;
  j["layers"] = layers;
  if (app.registration) {
    j["registration"] = {{"source", source},
                         {"target", target},
                         {"params", pipelineParamsToJson(app.registration->params())},
                         {"distance-check", paramsToJson(DistanceParams::schema(), app.registration->distanceParams())}};
    if (const ModelElementFilter& elements = app.registration->modelElements(); !elements.empty())
      j["registration"]["model-elements"] = {
          {"types", elements.types}, {"elements", elements.elements}, {"storeys", elements.storeys}};
    // Only features up to date for this source, target and parameters are marked so.
    const std::string detected_with = app.registration->featuresDetectedWith();
    if (!detected_with.empty()) j["registration"]["features-detected-with"] = json::parse(detected_with);
  }
  writeFileAtomically(path.toStdString(), [&](std::ostream& out) { out << j.dump(2) << "\n"; });
  showProjectInTitle(app.window, path);
}

namespace {

struct Entry {
  QString file;
  RigidTransform transform;
  bool visible = true;
  QString trajectory;  ///< attached to a mobile scan (empty: none)
  SavedStyle style;
  std::shared_ptr<const FeatureSet> features;  ///< detected, data frame (nullptr: none)
};

/// The source and target entries of the project's registration (-1: none) and the extraction
/// parameters their saved features were detected with (JSON text; empty: not up to date).
struct RegistrationSetup {
  int source = -1, target = -1;
  std::string features_detected_with;
};

json readJson(const QString& path) {
  std::ifstream in(path.toStdString());
  if (!in) throw FileError(path.toStdString(), "cannot open the project file");
  std::stringstream ss;
  ss << in.rdbuf();
  try {
    return json::parse(ss.str());
  } catch (const json::parse_error& e) {
    throw FileError(path.toStdString(), std::string("not valid JSON: ") + e.what(),
                    FileLocation{e.byte, std::nullopt, {}});
  }
}

/// The file as a whole: a Plumb project of this version with a "layers" array.
void checkProject(const json& j, const std::string& file) {
  if (!j.is_object() || !j.contains("plumb-project"))
    throw FileError(file, "not a Plumb project (no \"plumb-project\" key)");
  if (j.at("plumb-project") != kProjectVersion)
    throw FileError(file, "unsupported project version " + j.at("plumb-project").dump());
  if (!j.contains("layers") || !j.at("layers").is_array())
    throw FileError(file, "\"layers\" must be an array");
}

/// layers[i] (`e`): its file and trajectory (relative to `dir`), visibility and transform.
Entry readEntry(const json& e, std::size_t i, const QDir& dir, const std::string& file) {
  const std::string where = "layers[" + std::to_string(i) + "]";
  if (!e.is_object() || !e.contains("file") || !e.at("file").is_string())
    throw FileError(file, where + " needs a \"file\" string");
  Entry entry;
  entry.file = dir.absoluteFilePath(QString::fromStdString(e.at("file").get<std::string>()));
  entry.visible = e.value("visible", true);
  if (e.contains("trajectory")) {
    if (!e.at("trajectory").is_string()) throw FileError(file, where + ".trajectory must be a string");
    entry.trajectory = dir.absoluteFilePath(QString::fromStdString(e.at("trajectory").get<std::string>()));
  }
  if (e.contains("transform")) {
    try {
      entry.transform = transformFromJson(e.at("transform").dump(), file);
    } catch (const std::exception& ex) {
      throw FileError(file, where + ".transform: " + ex.what());
    }
  }
  if (e.contains("style") && !e.at("style").is_null()) {
    try {
      entry.style = styleFromJson(e.at("style"));
    } catch (const std::exception& ex) {
      throw FileError(file, where + "." + ex.what());
    }
  }
  if (e.contains("features")) {
    if (!e.at("features").is_string()) throw FileError(file, where + ".features must be a string");
    const QString features = dir.absoluteFilePath(QString::fromStdString(e.at("features").get<std::string>()));
    entry.features = std::make_shared<const FeatureSet>(readFeatureSetJson(features.toStdString()));
  }
  return entry;
}

/// Runs `read` on registration.<key> when the project has it; errors name the file and the key.
template <class Read>
void readSection(const json& registration, const char* key, const std::string& file, Read read) {
  if (!registration.contains(key)) return;
  try {
    read(registration.at(key));
  } catch (const std::exception& ex) {
    throw FileError(file, std::string("registration.") + key + ": " + ex.what());
  }
}

/// The project's registration setup; its parameters and the distance check's settings go to
/// the Registration dock at once.
RegistrationSetup readRegistration(AppContext& app, const json& j, const std::string& file) {
  if (!j.contains("registration") || !app.registration) return {};
  const json& r = j.at("registration");
  RegistrationSetup setup{r.value("source", -1), r.value("target", -1), {}};
  if (r.contains("features-detected-with")) setup.features_detected_with = r.at("features-detected-with").dump();
  PipelineParams params = app.registration->params();
  readSection(r, "params", file, [&](const json& v) {
    params = PipelineParams();
    pipelineParamsFromJson(v, params);
  });
  // Projects written before the distance check was saved keep the dock's current settings.
  DistanceParams distance = app.registration->distanceParams();
  readSection(r, "distance-check", file,
              [&](const json& v) {
                distance = DistanceParams();
                paramsFromJson(DistanceParams::schema(), v, distance);
              });
  // The model target's chosen elements; a project without them registers on the whole model.
  ModelElementFilter elements;
  readSection(r, "model-elements", file, [&](const json& v) {
    elements.types = v.value("types", std::vector<std::string>());
    elements.elements = v.value("elements", std::vector<std::string>());
    elements.storeys = v.value("storeys", std::vector<std::string>());
  });
  app.registration->params() = params;
  app.registration->distanceParams() = distance;
  app.registration->modelElements() = elements;
  app.registration->refreshParams();
  return setup;
}

/// Gives a loaded layer what its entry saved besides the file: transform, visibility, style,
/// features.
void restoreLayer(AppContext& app, Layer& layer, const Entry& entry) {
  setLayerTransform(app.scene, layer, entry.transform);
  layer.setVisible(entry.visible);
  applySavedStyle(app.scene, layer, entry.style);
  if (entry.features) {
    FeatureLayer& overlay = app.scene.addFeatures(QObject::tr("features"), entry.features, &layer);
    overlay.setTransform(layerTransform(layer));
  }
}

/// Loads the entries' files; each layer gets its entry's transform, visibility and trajectory.
/// `finish` runs when every file is loaded and every trajectory attached.
void loadEntries(AppContext& app, std::shared_ptr<const std::vector<Entry>> entries, ProjectDone finish) {
  QStringList files;
  for (const auto& e : *entries) files << e.file;
  auto layers = std::make_shared<std::vector<Layer*>>(entries->size(), nullptr);
  if (files.isEmpty()) {
    finish(true, *layers);
    return;
  }
  auto remaining = std::make_shared<int>(int(entries->size()));  // loads and attachments to wait for
  auto all_ok = std::make_shared<bool>(true);
  auto step = [remaining, all_ok, layers, finish](bool ok) {
    *all_ok = *all_ok && ok;
    if (--*remaining == 0) finish(*all_ok, *layers);
  };
  loadFiles(
      app, files,
      [&app, entries, layers, remaining, step](Layer& layer, const QString& p) {
        for (std::size_t i = 0; i < entries->size(); ++i)
          if (const Entry& entry = (*entries)[i]; entry.file == p && !(*layers)[i]) {
            (*layers)[i] = &layer;
            restoreLayer(app, layer, entry);
            if (!entry.trajectory.isEmpty() && layer.kind() == LayerKind::Dataset) {
              ++*remaining;
              startAttachTrajectory(app, static_cast<DatasetLayer&>(layer), entry.trajectory, step);
            }
            break;
          }
      },
      [step](const QString&, bool ok) { step(ok); });
}

}  // namespace

void openProject(AppContext& app, const QString& path, ProjectDone done) {
  if (app.tasks.holdsLayers())
    throw InputError("cannot open the project " + path.toStdString() +
                     " while a task works on the open layers: wait for it or cancel it");
  const json j = readJson(path);
  const std::string file = path.toStdString();
  checkProject(j, file);
  const QDir dir = QFileInfo(path).absoluteDir();
  auto entries = std::make_shared<std::vector<Entry>>();
  for (std::size_t i = 0; i < j.at("layers").size(); ++i) entries->push_back(readEntry(j.at("layers")[i], i, dir, file));
  const RegistrationSetup setup = readRegistration(app, j, file);
  app.undo.clear();
  app.scene.clear();
  showProjectInTitle(app.window, path);
  app.log.info(QObject::tr("Opening project %1 (%2 files)").arg(path).arg(qsizetype(entries->size())));
  loadEntries(app, entries, [&app, setup, done](bool ok, const std::vector<Layer*>& layers) {
    if (app.registration) {
      auto at = [&layers](int i) { return i >= 0 && std::size_t(i) < layers.size() ? layers[std::size_t(i)] : nullptr; };
      if (Layer* s = at(setup.source)) app.registration->setSourceLayer(s);
      if (Layer* t = at(setup.target)) app.registration->setTargetLayer(t);
      if (!setup.features_detected_with.empty())
        app.registration->adoptShownFeatures(setup.features_detected_with);
    }
    if (done) done(ok, layers);
  });
}

}  // namespace plumb::ui
