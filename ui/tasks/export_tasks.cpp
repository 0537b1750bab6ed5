#include "ui/tasks/export_tasks.hpp"

#include "common/error.hpp"
#include "io/io.hpp"
#include "io/stream/point_convert.hpp"
#include "quality/cloud_distance.hpp"
#include "ui/app_context.hpp"
#include "ui/layers/dataset_layer.hpp"
#include "ui/layers/layer_transform.hpp"
#include "ui/panels/log_panel.hpp"
#include "ui/tasks/load_budget.hpp"
#include "ui/tasks/task_manager.hpp"

namespace plumb::ui {

namespace {
void logResult(AppContext& app, Task* task, const QString& what, const QString& path) {
  QObject::connect(task, &Task::finished, &app.log, [&app, what, path](bool ok, const QString& msg) {
    if (ok) app.log.info(QObject::tr("%1 written to %2").arg(what, path));
    else app.log.error(QObject::tr("Cannot write %1: %2").arg(path, msg));
  });
}
/// What the writer had to convert or could not write (a dropped coordinate system, rescaled
/// intensities, skipped points): warnings in the log, as plumb-cli prints them as notes.
void logWriterNotes(AppContext& app, const QString& path, const std::vector<std::string>& notes) {
  for (const auto& n : notes)
    app.log.warning(QObject::tr("%1: %2").arg(path, QString::fromStdString(n)));
}
/// The distances the layer is coloured by, as each scan's "distance" field (none when the
/// layer shows no distances).
void attachShownDistances(Dataset& d, const std::vector<std::shared_ptr<const std::vector<float>>>& shown) {
  if (shown.empty()) return;
  std::vector<std::vector<float>> per_scan;
  for (const auto& s : shown) per_scan.push_back(s ? *s : std::vector<float>{});
  attachDistanceField(d, per_scan);
}
/// The layer holds a subsample (opened above the memory budget): the whole file is streamed
/// through the transform (convertPointFile, as plumb-cli convert --transform), so no point of
/// the user's data is lost. The subsample's distances are not exported.
Task* exportWholeFile(AppContext& app, const DatasetLayer& layer, const RigidTransform& T, const QString& path) {
  if (layer.hasDistances())
    app.log.warning(QObject::tr("%1: distances were computed on the subsample and are not exported "
                                "with the whole file").arg(path));
  const std::filesystem::path source = layer.dataset().source;
  const std::uint64_t budget = memoryBudget(app);
  return app.tasks.run(QObject::tr("Exporting %1").arg(layer.name()),
                       [&app, source, T, path, budget](Progress& progress) -> Task::Apply {
                         ConvertParams params;
                         params.transform = T;
                         params.memory_budget = budget;
                         params.stream = streamOptionsWithin(budget);
                         ConvertResult r = convertPointFile(source, path.toStdString(), params, &progress);
                         std::vector<std::string> notes;
                         for (const auto& f : r.files) notes.insert(notes.end(), f.report.notes.begin(), f.report.notes.end());
                         return [&app, path, notes] { logWriterNotes(app, path, notes); };
                       });
}
}  // namespace

Task* exportRegisteredDataset(AppContext& app, const Layer& layer, const QString& path) {
  if (layer.kind() != LayerKind::Dataset)
    throw InputError("export: '" + layer.name().toStdString() + "' is not a point dataset");
  const auto& dataset_layer = static_cast<const DatasetLayer&>(layer);
  const auto data = dataset_layer.sharedDataset();
  refuseSameFile(data->source, path.toStdString());  // an export never replaces its own input
  const RigidTransform T = layerTransform(layer);
  if (dataset_layer.subsampledFrom()) {
    Task* task = exportWholeFile(app, dataset_layer, T, path);
    logResult(app, task, QObject::tr("Registered %1 (the whole file)").arg(layer.name()), path);
    return task;
  }
  Task* task = app.tasks.run(QObject::tr("Exporting %1").arg(layer.name()),
                             [&app, data, T, path, distances = dataset_layer.distances()](
                                 Progress& progress) -> Task::Apply {
                               Dataset moved = *data;
                               moved.transform(T);
                               attachShownDistances(moved, distances);
                               WriteReport report;
                               WriteOptions options;
                               options.report = &report;
                               writeDataset(path.toStdString(), moved, options, &progress);
                               return [&app, path, notes = report.notes] {
                                 logWriterNotes(app, path, notes);
                               };
                             });
  logResult(app, task, QObject::tr("Registered %1").arg(layer.name()), path);
  return task;
}

Task* exportTransform(AppContext& app, const Layer& layer, const QString& path) {
  const RigidTransform T = layerTransform(layer);
  Task* task = app.tasks.run(QObject::tr("Exporting transform"), [T, path](Progress&) -> Task::Apply {
    writeTransformFile(path.toStdString(), T);
    return {};
  });
  logResult(app, task, QObject::tr("Transform of %1").arg(layer.name()), path);
  return task;
}

}  // namespace plumb::ui
