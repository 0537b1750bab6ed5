#include "ui/tasks/add_dataset.hpp"

#include <QFileInfo>
#include <QObject>

#include "ui/layers/dataset_layer.hpp"
#include "ui/layers/prepared_dataset.hpp"
#include "ui/layers/scene.hpp"
#include "ui/tasks/task_manager.hpp"

namespace plumb::ui {

Task* addDatasetInBackground(TaskManager& tasks, Scene& scene, std::shared_ptr<const Dataset> data,
                             OnDatasetAdded added) {
  const QString name =
      data->source.empty() ? QObject::tr("dataset")
                           : QFileInfo(QString::fromStdString(data->source.string())).fileName();
  return tasks.run(QObject::tr("Preparing %1").arg(name),
                   [&scene, data = std::move(data), added](Progress& progress) -> Task::Apply {
                     auto prepared = std::make_shared<PreparedDataset>(prepareDataset(data, &progress));
                     return [&scene, data, prepared, added] {
                       DatasetLayer& layer = scene.addDataset(data, std::move(*prepared));
                       if (added) added(layer);
                     };
                   });
}

}  // namespace plumb::ui
