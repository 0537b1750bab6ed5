#include "ui/tasks/load_files.hpp"

#include <QFileInfo>

#include <algorithm>
#include <chrono>
#include <memory>
#include <optional>
#include <variant>

#include "io/io.hpp"
#include "io/lod/lod_cache.hpp"
#include "io/lod/lod_subsample.hpp"
#include "registration/bounded/bounded_input.hpp"
#include "ui/actions/recent_files.hpp"
#include "ui/app_context.hpp"
#include "ui/layers/dataset_layer.hpp"
#include "ui/layers/model_layer.hpp"
#include "ui/layers/prepared_dataset.hpp"
#include "ui/layers/scene.hpp"
#include "ui/panels/log_panel.hpp"
#include "ui/registration/registration_panel.hpp"
#include "ui/lod/detail_cache_task.hpp"
#include "ui/tasks/load_budget.hpp"
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
  std::optional<SubsampledFrom> subsampled;  ///< the dataset is a subsample (memory budget)
  /// How the subsample was made: from the level-of-detail cache (and how long it took), or
  /// why the file was streamed although a cache exists.
  QString subsample_route;
  std::uint64_t budget_share = 0;  ///< bytes this file was allowed (LoadLimits::budget)
};

double gigabytes(std::uint64_t bytes) { return double(bytes) / (1024.0 * 1024.0 * 1024.0); }

/// Fraction of a load's progress bar for reading (the rest prepares the display data).
constexpr double kReadShare = 0.8;

/// What bounds a load, taken on the UI thread when it starts.
struct LoadLimits {
  std::uint64_t budget = 0;  ///< bytes this file may take (loadShare), 0: no budget
  double voxel = 0.02;       ///< subsample voxel, metres
  std::filesystem::path cache_root;  ///< level-of-detail caches (lodCacheRoot)
};

LoadLimits loadLimits(AppContext& app, std::size_t point_files) {
  const PipelineParams params = app.registration ? app.registration->params() : PipelineParams{};
  return {loadShare(app, point_files), subsampleVoxel(params), lodCacheRoot()};
}

/// A file that holds points, by its extension: the point files opened together share what the
/// budget leaves (a .ply may still turn out to be a mesh: it then leaves its share unused).
bool holdsPoints(const QString& path) { return !isModelFormat(formatFromExtension(path.toStdString())); }

/// The subsample from the file's level-of-detail cache when a valid one exists (a reopen:
/// seconds instead of streaming the file), else nullopt; `route` says which and why.
std::optional<SubsampleResult> subsampleFromCache(const std::string& path, const SubsampleParams& plan,
                                                  const LoadLimits& limits, Progress& reading, QString& route) {
  const LodCacheOpenResult open = openLodCache(path, limits.cache_root);
  if (!open.valid()) return std::nullopt;
  const auto t0 = std::chrono::steady_clock::now();
  LodSubsampleResult r = subsampleFromLodCache(path, *open.cache, plan, &reading);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!r.subsample) {
    route = QObject::tr("its level-of-detail cache cannot give the subsample (%1): the file was streamed")
                .arg(QString::fromStdString(r.why_not));
    return std::nullopt;
  }
  route = QObject::tr("made from its level-of-detail cache in %1 s (%2 points of %3 levels)")
              .arg(seconds, 0, 'f', 1).arg(r.points_from_cache).arg(r.levels);
  return std::move(r.subsample);
}

/// readFile, or a voxel subsample when the whole file would not fit the budget (from the
/// file's level-of-detail cache when it has a valid one).
LoadedData readWithin(const std::string& path, const LoadLimits& limits, Progress& reading, Loaded& out) {
  const std::optional<SubsampleParams> plan = planLoad(path, limits.budget, limits.voxel);
  if (!plan) return readFile(path, ReadOptions{}, &reading);
  std::optional<SubsampleResult> s = subsampleFromCache(path, *plan, limits, reading, out.subsample_route);
  if (!s) s = subsampleDataset(path, *plan, StreamOptions{}, &reading);
  out.subsampled = SubsampledFrom{s->points_read, s->voxel};
  return std::move(s->data);
}

Loaded readAndPrepare(const std::string& path, const LoadLimits& limits, Progress& progress) {
  Progress reading = progress.sub(0.0, kReadShare);
  Loaded out;
  out.budget_share = limits.budget;
  LoadedData data = readWithin(path, limits, reading, out);
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
    auto& dataset_layer = app.scene.addDataset(data.dataset, std::move(data.prepared));
    layer = &dataset_layer;
    app.log.info(QObject::tr("Loaded %1: %2 points in %3 scan(s)")
                     .arg(QFileInfo(path).fileName())
                     .arg(points)
                     .arg(scans));
    if (data.subsampled) {
      dataset_layer.setSubsampledFrom(*data.subsampled);
      app.log.warning(QObject::tr("%1 holds %2 points: showing it whole would exceed its part of the "
                                  "memory budget (%3 of %4 GB), so it is shown and registered as a "
                                  "%5 cm voxel subsample; exports read the whole file")
                          .arg(QFileInfo(path).fileName())
                          .arg(data.subsampled->points_in_file)
                          .arg(gigabytes(data.budget_share), 0, 'f', 2)
                          .arg(gigabytes(memoryBudget(app)), 0, 'f', 2)
                          .arg(data.subsampled->voxel * 100.0, 0, 'f', 1));
      if (!data.subsample_route.isEmpty())
        app.log.info(QObject::tr("%1: the subsample was %2").arg(QFileInfo(path).fileName(), data.subsample_route));
      startDetailCache(app, dataset_layer, data.budget_share);  // full resolution where the view needs it
    }
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
  const LoadLimits limits =
      loadLimits(app, static_cast<std::size_t>(std::count_if(paths.begin(), paths.end(), holdsPoints)));
  for (const QString& path : paths) {
    const QString absolute = QFileInfo(path).absoluteFilePath();
    // Held until the file is a layer (then its points count in heldBytes) or has failed.
    const std::uint64_t reserved = holdsPoints(path) ? limits.budget : 0;
    app.loads_reserved += reserved;
    app.log.info(QObject::tr("Loading %1").arg(absolute));
    Task* task = app.tasks.run(
        QObject::tr("Loading %1").arg(QFileInfo(path).fileName()),
        [&app, absolute, path, on_loaded, limits](Progress& progress) -> Task::Apply {
          auto data = std::make_shared<Loaded>(readAndPrepare(absolute.toStdString(), limits, progress));
          return [&app, data, absolute, path, on_loaded] {
            Layer& layer = addLoaded(app, *data, absolute);
            if (on_loaded) on_loaded(layer, path);
          };
        });
    QObject::connect(task, &Task::finished, &app.log,
                     [&app, absolute, path, on_done, reserved](bool ok, const QString& msg) {
                       app.loads_reserved -= std::min(app.loads_reserved, reserved);
                       if (!ok) app.log.error(QObject::tr("Cannot load %1: %2").arg(absolute, msg));
                       if (on_done) on_done(path, ok);
                     });
  }
}

}  // namespace plumb::ui
