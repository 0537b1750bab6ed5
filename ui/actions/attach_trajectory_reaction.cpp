#include "ui/actions/attach_trajectory_reaction.hpp"

#include <QMainWindow>

#include "ui/actions/file_dialogs.hpp"
#include "ui/app_context.hpp"
#include "ui/layers/dataset_layer.hpp"
#include "ui/panels/layer_tree_panel.hpp"
#include "ui/panels/log_panel.hpp"
#include "ui/tasks/attach_trajectory.hpp"

namespace plumb::ui {

void AttachTrajectoryReaction::onTriggered() {
  Layer* layer = app().layers.currentRootLayer();
  if (!layer || layer->kind() != LayerKind::Dataset) {
    app().log.error(tr("Attach trajectory: select the mobile scan (a point dataset) first"));
    return;
  }
  const QString path = chooseFileToOpen(&app().window, FolderKind::Data, tr("Attach trajectory to %1").arg(layer->name()),
                                        tr("Trajectory, t x y z per line (*.txt *.csv *.traj);;All files (*)"));
  if (path.isEmpty()) return;
  startAttachTrajectory(app(), static_cast<DatasetLayer&>(*layer), path);
}

}  // namespace plumb::ui
