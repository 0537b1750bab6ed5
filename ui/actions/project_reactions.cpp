#include "ui/actions/project_reactions.hpp"

#include <QMainWindow>

#include "ui/actions/file_dialogs.hpp"
#include "ui/app_context.hpp"
#include "ui/panels/log_panel.hpp"
#include "ui/project/project_file.hpp"
#include "ui/tasks/task_manager.hpp"

namespace plumb::ui {

namespace {
QString filter() { return QObject::tr("Plumb project (*.plumb.json);;JSON (*.json)"); }
}  // namespace

OpenProjectReaction::OpenProjectReaction(QAction* action, AppContext& app) : Reaction(action, app) {
  followTasks();
}

bool OpenProjectReaction::canRun() const { return !app().tasks.holdsLayers(); }

void OpenProjectReaction::onTriggered() {
  const QString path =
      chooseFileToOpen(&app().window, tr("Open project"), filter());
  if (path.isEmpty()) return;
  try {
    openProject(app(), path);
  } catch (const std::exception& e) {
    app().log.error(QString::fromUtf8(e.what()));
  }
}

void SaveProjectReaction::onTriggered() {
  QString path = chooseFileToSave(&app().window, tr("Save project"),
                                              "project.plumb.json", filter());
  if (path.isEmpty()) return;
  if (!path.endsWith(".json", Qt::CaseInsensitive)) path += ".plumb.json";
  try {
    saveProject(app(), path);
    app().log.info(tr("Project saved to %1").arg(path));
  } catch (const std::exception& e) {
    app().log.error(QString::fromUtf8(e.what()));
  }
}

}  // namespace plumb::ui
