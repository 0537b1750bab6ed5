#include "ui/tasks/load_files.hpp"

#include <QFileInfo>

#include <memory>
#include <variant>

#include "io/io.hpp"
#include "ui/actions/recent_files.hpp"
#include "ui/app_context.hpp"
#include "ui/layers/dataset_layer.hpp"
#include "ui/layers/model_layer.hpp"
#include "ui/layers/prepared_dataset.hpp"
#include "ui/layers/scene.hpp"
#include "ui/panels/log_panel.hpp"
#include "ui/tasks/task_manager.hpp"
#include "ui/view/scene_framing.hpp"
#include "ui/view/vtk_view_widget.hpp"

namespace plumb::ui {

QString supportedFileFilter() {
  return QObject::tr(
      "Survey data (*.e57 *.las *.laz *.ply *.pcd *.xyz *.txt *.csv *.pts *.asc *.ifc *.obj "
      "*.gltf *.glb *.fbx *.dae *.stl);;Point clouds (*.e57 *.las *.laz *.ply *.pcd *.xyz *.txt "
      "*.csv *.pts *.asc);;Models (*.ifc *.obj *.gltf *.glb *.fbx *.dae *.stl *.ply);;All files (*)");
}

namespace {

/// A file read and made ready to show, off the UI thread: a dataset with its display data
/// (random point order, colours) or a model.
struct Loaded {
  std::shared_ptr<const Dataset> dataset;
  PreparedDataset prepared;
  std::shared_ptr<const BimModel> model;
};

/// Fraction of a load's progress bar for reading (the rest prepares the display data).
constexpr double kReadShare = 0.8;

Loaded readAndPrepare(const std::string& path, Progress& progress) {
  Progress reading = progress.sub(0.0, kReadShare);
  LoadedData data = readFile(path, ReadOptions{}, &reading);
  Loaded out;
  if (auto* dataset = std::get_if<Dataset>(&data)) {
    out.dataset = std::make_shared<const Dataset>(std::move(*dataset));
    Progress preparing = progress.sub(kReadShare, 1.0);
    out.prepared = prepareDataset(out.dataset, &preparing);
  } else {
    out.model = std::make_shared<const BimModel>(std::move(std::get<BimModel>(data)));
  }
  return out;
}

/// Adds the loaded data as a layer (on the UI thread: VTK objects around prepared buffers);
/// frames the camera when it is the first layer.
Layer& addLoaded(AppContext& app, Loaded& data, const QString& path) {
  const bool first = app.scene.layers().empty();
  Layer* layer = nullptr;
  if (data.dataset) {
    const auto points = data.dataset->pointCount();
    const auto scans = data.dataset->scans.size();
    layer = &app.scene.addDataset(data.dataset, std::move(data.prepared));
    app.log.info(QObject::tr("Loaded %1: %2 points in %3 scan(s)")
                     .arg(QFileInfo(path).fileName())
                     .arg(points)
                     .arg(scans));
  } else {
    const auto triangles = data.model->mesh.triangleCount();
    const auto elements = data.model->elements.size();
    layer = &app.scene.addModel(data.model);
    app.log.info(QObject::tr("Loaded %1: %2 triangles, %3 elements")
                     .arg(QFileInfo(path).fileName())
                     .arg(triangles)
                     .arg(elements));
  }
  app.recent.add(path);
  if (first) frameScene(app.scene, app.view);
  else app.view.requestRender();
  return *layer;
}

}  // namespace

void loadFiles(AppContext& app, const QStringList& paths, OnLoaded on_loaded, OnFileDone on_done) {
  for (const QString& path : paths) {
    const QString absolute = QFileInfo(path).absoluteFilePath();
    app.log.info(QObject::tr("Loading %1").arg(absolute));
    Task* task = app.tasks.run(
        QObject::tr("Loading %1").arg(QFileInfo(path).fileName()),
        [&app, absolute, path, on_loaded](Progress& progress) -> Task::Apply {
          auto data = std::make_shared<Loaded>(readAndPrepare(absolute.toStdString(), progress));
          return [&app, data, absolute, path, on_loaded] {
            Layer& layer = addLoaded(app, *data, absolute);
            if (on_loaded) on_loaded(layer, path);
          };
        });
    QObject::connect(task, &Task::finished, &app.log,
                     [&app, absolute, path, on_done](bool ok, const QString& msg) {
                       if (!ok) app.log.error(QObject::tr("Cannot load %1: %2").arg(absolute, msg));
                       if (on_done) on_done(path, ok);
                     });
  }
}

}  // namespace plumb::ui
