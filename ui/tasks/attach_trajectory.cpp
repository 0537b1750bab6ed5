#include "ui/tasks/attach_trajectory.hpp"

#include <QObject>

#include <memory>

#include "model/dataset.hpp"
#include "model/trajectory.hpp"
#include "ui/app_context.hpp"
#include "ui/layers/dataset_layer.hpp"
#include "ui/layers/scene.hpp"
#include "ui/panels/log_panel.hpp"
#include "ui/tasks/task_manager.hpp"

namespace plumb::ui {

Task* startAttachTrajectory(AppContext& app, DatasetLayer& layer, const QString& path,
                            std::function<void(bool ok)> done) {
  const std::shared_ptr<const Dataset> data = layer.sharedDataset();
  const std::string file = path.toStdString();
  // The layer may be removed while the task runs (by other means than the disabled actions):
  // never touch it then.
  const LayerRef held(layer);
  const QString name = layer.name();
  Task* task = app.tasks.run(
      QObject::tr("Attaching trajectory to %1").arg(name),
      [&app, data, file, path, held, name](Progress& progress) -> Task::Apply {
        reportProgress(&progress, 0.0, "reading the trajectory");
        const Trajectory trajectory = readTrajectory(file);
        checkCanceled(&progress);
        reportProgress(&progress, 0.3, "interpolating sensor origins");
        auto with_origins = std::make_shared<Dataset>(*data);
        setSensorOriginsFromTrajectory(*with_origins, trajectory, file);
        const std::size_t poses = trajectory.times.size();
        return [&app, with_origins, path, held, name, poses] {
          auto* target = static_cast<DatasetLayer*>(&stillThere(held, name, "the trajectory attachment"));
          target->attachTrajectory(with_origins, path);
          app.scene.layerChanged(target);
          app.log.info(QObject::tr("%1: sensor origins of %2 points from the trajectory %3 (%4 poses)")
                           .arg(target->name())
                           .arg(with_origins->pointCount())
                           .arg(path)
                           .arg(poses));
        };
      },
      {held});
  QObject::connect(task, &Task::finished, &app.scene, [&app, done](bool ok, const QString& message) {
    if (!ok && message != QLatin1String("cancelled")) app.log.error(message);
    if (done) done(ok);
  });
  return task;
}

}  // namespace plumb::ui
