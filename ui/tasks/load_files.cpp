#include "ui/tasks/load_files.hpp"

#include <QFileInfo>

#include <memory>
#include <variant>

#include "io/io.hpp"
#include "ui/actions/recent_files.hpp"
#include "ui/app_context.hpp"
#include "ui/layers/dataset_layer.hpp"
#include "ui/layers/model_layer.hpp"
#include "ui/layers/scene.hpp"
#include "ui/panels/log_panel.hpp"
#include "ui/tasks/task_manager.hpp"
#include "ui/view/standard_view.hpp"
#include "ui/view/vtk_view_widget.hpp"

namespace plumb::ui {

QString supportedFileFilter() {
  return QObject::tr(
      "Survey data (*.e57 *.las *.laz *.ply *.pcd *.xyz *.txt *.csv *.pts *.asc *.ifc *.obj "
      "*.gltf *.glb *.fbx *.dae *.stl);;Point clouds (*.e57 *.las *.laz *.ply *.pcd *.xyz *.txt "
      "*.csv *.pts *.asc);;Models (*.ifc *.obj *.gltf *.glb *.fbx *.dae *.stl *.ply);;All files (*)");
}

namespace {

/// Adds the loaded data as a layer; frames the camera when it is the first layer.
Layer& addLoaded(AppContext& app, LoadedData& data, const QString& path) {
  const bool first = app.scene.layers().empty();
  Layer* layer = nullptr;
  if (auto* dataset = std::get_if<Dataset>(&data)) {
    const auto points = dataset->pointCount();
    const auto scans = dataset->scans.size();
    layer = &app.scene.addDataset(std::make_shared<const Dataset>(std::move(*dataset)));
    app.log.info(QObject::tr("Loaded %1: %2 points in %3 scan(s)")
                     .arg(QFileInfo(path).fileName())
                     .arg(points)
                     .arg(scans));
  } else {
    auto& model = std::get<BimModel>(data);
    const auto triangles = model.mesh.triangleCount();
    const auto elements = model.elements.size();
    layer = &app.scene.addModel(std::make_shared<const BimModel>(std::move(model)));
    app.log.info(QObject::tr("Loaded %1: %2 triangles, %3 elements")
                     .arg(QFileInfo(path).fileName())
                     .arg(triangles)
                     .arg(elements));
  }
  app.recent.add(path);
  if (first) resetCamera(app.view.renderer());
  app.view.requestRender();
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
          auto data = std::make_shared<LoadedData>(
              readFile(absolute.toStdString(), ReadOptions{}, &progress));
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
